// SPDX-License-Identifier: MIT
#include "fuzz/fuzz_targets.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>

#include "core/errors.h"
#include "datasets/dataset_request.h"
#include "datasets/input_warnings.h"
#include "datasets/io/mat.h"
#include "datasets/io/npy.h"
#include "datasets/io/pickle.h"
#include "datasets/readers/coco_detections.h"
#include "datasets/readers/colmap_text.h"
#include "datasets/readers/fourda_calibration.h"
#include "datasets/readers/fourda_text.h"
#include "datasets/readers/generic_detections.h"
#include "datasets/readers/generic_labels.h"
#include "datasets/readers/hdf5_cache.h"
#include "datasets/readers/human36m.h"
#include "datasets/readers/mvor.h"
#include "datasets/readers/openpose_json.h"
#include "datasets/readers/panoptic.h"
#include "datasets/readers/voxelpose_calibration.h"
#include "datasets/readers/voxelpose_detections.h"

namespace rpt::fuzz {
namespace {

namespace fs = std::filesystem;

// A folder of this process for the files the path-taking readers open (in memory when /dev/shm
// exists), removed when the process exits normally.
class Scratch {
 public:
  Scratch() {
    std::error_code ec;
    const fs::path base = fs::is_directory("/dev/shm", ec) ? fs::path("/dev/shm") : fs::temp_directory_path();
    dir_ = base / ("rpt_fuzz_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  ~Scratch() {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  const fs::path& dir() const { return dir_; }

 private:
  fs::path dir_;
};

const fs::path& ScratchDir() {
  static const Scratch scratch;
  return scratch.dir();
}

// Writes `bytes` to `relative` under the scratch folder and returns the path.
fs::path WriteScratch(const fs::path& relative, std::span<const std::uint8_t> bytes) {
  const fs::path path = ScratchDir() / relative;
  fs::create_directories(path.parent_path());
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) throw std::runtime_error("fuzz harness: cannot write " + path.string());
  const bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
  if (std::fclose(f) != 0 || !ok) throw std::runtime_error("fuzz harness: cannot write " + path.string());
  return path;
}

fs::path WriteScratch(const fs::path& relative, const std::string& text) {
  return WriteScratch(relative, std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

std::string Text(std::span<const std::uint8_t> bytes) { return std::string(bytes.begin(), bytes.end()); }

// A fixed, valid Panoptic calibration with one HD camera 00_00 2 m in front of the origin, and a
// valid body file with one person; each Panoptic target fuzzes one of the two.
const char* const kPanopticCalibration =
    R"({"calibDataSource": "fuzz", "cameras": [{"name": "00_00", "type": "hd", "resolution": [1920, 1080],
  "K": [[1500, 0, 960], [0, 1500, 540], [0, 0, 1]], "distCoef": [-0.2, 0.15, 0.001, -0.0005, 0.02],
  "R": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "t": [[0], [100], [400]]}]})";

}  // namespace

std::string PanopticCalibrationText() { return kPanopticCalibration; }

std::string PanopticBodiesText() {
  std::string joints;
  for (int j = 0; j < 19; ++j) joints += (j ? ", " : "") + std::to_string(10 + j) + ", " + std::to_string(-150 + 5 * j) + ", 20, 0.8";
  return R"({"version": 0.7, "univTime": 1.5, "fpsType": "hd_29_97", "bodies": [{"id": 3, "joints19": [)" + joints + "]}]}";
}

namespace {

void ReadPanopticWith(const std::string& calibration, const std::string& bodies) {
  const fs::path root = ScratchDir() / "panoptic";
  fs::remove_all(root);
  WriteScratch("panoptic/seqA/calibration_seqA.json", calibration);
  WriteScratch("panoptic/seqA/hdPose3d_stage1_coco19/body3DScene_00000010.json", bodies);
  ReadPanoptic(DatasetRequest{"panoptic", root, {{"sequences", "seqA"}, {"cameras", "00_00"}, {"every", "1"}}});
}

// Frames shelf_000000..shelf_000003 seen by cameras "0" and "1", for the VoxelPose cache.
const Sequence& VoxelPoseSequence() {
  static const Sequence sequence = [] {
    Sequence s;
    s.name = "shelf";
    for (const char* name : {"0", "1"}) {
      Camera camera;
      camera.name = name;
      s.cameras.push_back(camera);
    }
    for (int f = 0; f < 4; ++f) {
      SequenceFrame frame;
      frame.id = "shelf_00000" + std::to_string(f);
      s.frames.push_back(frame);
    }
    return s;
  }();
  return sequence;
}

void ReadHdf5Cache(std::span<const std::uint8_t> bytes) {
  const fs::path path = WriteScratch("cache.h5", bytes);
  const Hdf5CacheContents contents = ProbeHdf5Cache(path);
  if (contents.sequences) ReadSequencesHdf5(path);
  if (contents.detections) ReadDetectionsHdf5(path);
}

std::vector<FuzzTarget> MakeTargets() {
  using B = std::span<const std::uint8_t>;
  return {
      {"labels", "generic JSON labels (rpt / skelda)", [](B b) { ReadLabels(WriteScratch("labels.json", b)); }},
      {"detections_json", "generic JSON detections", [](B b) { ReadGenericDetections(WriteScratch("detections.json", b)); }},
      {"coco", "COCO keypoint result list (MVOR image ids)", [](B b) { ReadCocoDetections(WriteScratch("results.json", b)); }},
      {"openpose", "OpenPose *_keypoints.json (one file of a camera folder)",
       [](B b) {
         fs::remove_all(ScratchDir() / "openpose");
         WriteScratch("openpose/cam0/v_000000000001_keypoints.json", b);
         ReadOpenPoseFolder(ScratchDir() / "openpose");
       }},
      {"voxelpose_calibration", "VoxelPose calibration_<dataset>.json",
       [](B b) {
         InputWarnings warnings;
         ReadVoxelPoseCalibration(WriteScratch("calibration.json", b), 1032, 776, &warnings);
       }},
      {"voxelpose_detections", "VoxelPose detection cache (pickle)",
       [](B b) { ReadVoxelPoseDetections(WriteScratch("pred.pkl", b), VoxelPoseSequence(), "shelf"); }},
      {"pickle", "Python pickle (allow-listed classes)", [](B b) { io::ParsePickle(b, "fuzz.pkl"); }},
      {"npy", "NumPy .npy", [](B b) { io::ParseNpy(b, "fuzz.npy"); }},
      {"npz", "NumPy .npz (ZIP, stored or deflated)", [](B b) { io::ParseNpz(b, "fuzz.npz"); }},
      {"mat", "MATLAB v5 .mat", [](B b) { io::ParseMat(b, "fuzz.mat"); }},
      {"hdf5", "rpt HDF5 cache (sequences and detections)", ReadHdf5Cache},
      {"colmap_cameras", "COLMAP cameras.txt",
       [](B b) {
         std::istringstream in(Text(b));
         ParseColmapCamerasText(in, "cameras.txt");
       }},
      {"colmap_images", "COLMAP images.txt",
       [](B b) {
         std::istringstream in(Text(b));
         InputWarnings warnings;
         ParseColmapImagesText(in, "images.txt", &warnings);
       }},
      {"fourda_detections", "4D-Association detection text",
       [](B b) {
         InputWarnings warnings;
         ParseFourDaDetections(Text(b), "detection.txt", &warnings);
       }},
      {"fourda_skeletons", "4D-Association skeleton text (gt.txt)", [](B b) { ParseFourDaSkeletons(Text(b), "gt.txt"); }},
      {"fourda_calibration", "4D-Association calibration.json",
       [](B b) {
         InputWarnings warnings;
         ReadFourDaCalibration(WriteScratch("calibration_4da.json", b), &warnings);
       }},
      {"panoptic_calibration", "CMU Panoptic calibration_<seq>.json",
       [](B b) { ReadPanopticWith(Text(b), PanopticBodiesText()); }},
      {"panoptic_bodies", "CMU Panoptic body3DScene_<n>.json",
       [](B b) { ReadPanopticWith(kPanopticCalibration, Text(b)); }},
      {"mvor", "MVOR camma_mvor_2018.json",
       [](B b) {
         const fs::path root = ScratchDir() / "mvor";
         fs::remove_all(root);
         WriteScratch("mvor/camma_mvor_2018.json", b);
         ReadMvor(DatasetRequest{"mvor", root, {{"days", "1"}, {"detections", "none"}}});
       }},
      {"h36m_metadata_xml", "Human3.6M metadata.xml cameras",
       [](B b) { ReadHuman36mCameras(WriteScratch("metadata.xml", b), "S1", DistortionModel::kOpenCV, nullptr); }},
  };
}

}  // namespace

const std::vector<FuzzTarget>& FuzzTargets() {
  static const std::vector<FuzzTarget> targets = MakeTargets();
  return targets;
}

const FuzzTarget* FindFuzzTarget(std::string_view name) {
  for (const FuzzTarget& target : FuzzTargets()) {
    if (target.name == name) return &target;
  }
  return nullptr;
}

bool RunFuzzTarget(const FuzzTarget& target, std::span<const std::uint8_t> bytes) {
  try {
    target.read(bytes);
    return true;
  } catch (const InputError&) {
    return false;
  } catch (const ConfigError&) {
    return false;
  }
}

}  // namespace rpt::fuzz
