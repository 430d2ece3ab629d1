// SPDX-License-Identifier: MIT
#include "fuzz/fuzz_targets.h"

#include <unistd.h>
#include <zlib.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "core/errors.h"
#include "engine/config.h"
#include "engine/report/report_data.h"
#include "engine/report/report_run.h"
#include "engine/sweep_configurations.h"
#include "engine/thresholds_file.h"
#include "datasets/calibration/calibration.h"
#include "datasets/dataset_request.h"
#include "datasets/frame_source.h"
#include "datasets/input_warnings.h"
#include "datasets/io/mat.h"
#include "datasets/io/npy.h"
#include "datasets/io/pickle.h"
#include "datasets/io/input_limits.h"
#include "datasets/io/line_reader.h"
#include "datasets/readers/coco_detections.h"
#include "datasets/readers/detection_lines.h"
#include "datasets/readers/colmap_text.h"
#include "datasets/readers/egohumans.h"
#include "datasets/readers/fourda_calibration.h"
#include "datasets/readers/fourda_text.h"
#include "datasets/readers/generic_detections.h"
#include "datasets/readers/generic_labels.h"
#include "datasets/readers/h3wb.h"
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

// Four cameras at the corners of a 3.6 x 10 m room, 1.5 m high, looking at a point 0.9 m above
// the origin. Each subject's cameras are moved by 25 mm x subject x (camera - 1.5) along x, so the
// views of one frame agree (within the readers' 1 cm) for one subject's cameras only.
std::string H36mMetadataXmlText() {
  static const std::string text = [] {
    const double corners[4][2] = {{1.8, 5.0}, {1.8, -5.1}, {-1.8, 5.2}, {-1.8, -3.7}};
    std::vector<double> w0(300, 0.0);
    for (int s = 1; s <= 11; ++s) {
      for (int c = 0; c < 4; ++c) {
        const Eigen::Vector3d center(corners[c][0] + 0.025 * s * (c - 1.5), corners[c][1], 1.5);
        // world -> camera rotation looking at the target (x right, y down, z forward; world z up)
        const Eigen::Vector3d z = (Eigen::Vector3d(0, 0, 0.9) - center).normalized();
        const Eigen::Vector3d x = z.cross(Eigen::Vector3d::UnitZ()).normalized();
        const Eigen::Vector3d y = z.cross(x);
        Eigen::Matrix3d R;
        R << x.transpose(), y.transpose(), z.transpose();
        // metadata.xml angles: R = Rx(a) Ry(b) Rz(c)
        const double angles[3] = {std::atan2(-R(1, 2), R(2, 2)), std::asin(std::clamp(R(0, 2), -1.0, 1.0)),
                                  std::atan2(-R(0, 1), R(0, 0))};
        const std::size_t o = static_cast<std::size_t>(6 * (c * 11 + (s - 1)));
        for (int i = 0; i < 3; ++i) w0[o + static_cast<std::size_t>(i)] = angles[i];
        for (int i = 0; i < 3; ++i) w0[o + 3 + static_cast<std::size_t>(i)] = 1000.0 * center[i];
      }
    }
    for (int c = 0; c < 4; ++c) {
      const double intrinsics[9] = {1145.0 + c, 1144.0 + c, 512.5 - c, 515.5 + c, -0.2, 0.25, -0.003, -0.0014, -0.001};
      for (int i = 0; i < 9; ++i) w0[static_cast<std::size_t>(264 + 9 * c + i)] = intrinsics[i];
    }
    std::string out = "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<metadata>\n  <w0>[";
    char number[32];
    for (std::size_t i = 0; i < w0.size(); ++i) {
      std::snprintf(number, sizeof(number), "%.17g", w0[i]);
      out += (i ? " " : "") + std::string(number);
    }
    return out + "]</w0>\n</metadata>\n";
  }();
  return text;
}

// Exo cameras 1 (fisheye, as EgoHumans' GoPros) and 2 (pinhole) and an Aria camera (1408 x 1408,
// not an exo camera).
std::string EgohumansCamerasText() {
  return "# Camera list with one line of data per camera:\n#   CAMERA_ID, MODEL, WIDTH, HEIGHT, PARAMS[]\n"
         "1 OPENCV_FISHEYE 3840 2160 1750 1752 1920 1080 0.05 -0.01 0.002 -0.0003\n"
         "2 PINHOLE 1920 1080 1000 1001 960 540\n"
         "3 FOV 1408 1408 600 600 704 704 0.9\n";
}

// Images of cam01 at time stamps 1 and 50 (the one nearest the first GT time stamp, 1, is used),
// cam02 at 3, and the Aria camera.
std::string EgohumansImagesText() {
  return "# Image list with two lines of data per image:\n#   IMAGE_ID, QW, QX, QY, QZ, TX, TY, TZ, CAMERA_ID, NAME\n"
         "1 0.7071068 -0.7071068 0 0 0.2 1.5 4 1 cam01/00001.jpg\n100.5 200.5 12 300 400 -1\n"
         "2 0.7071068 -0.7071068 0 0 0.7 1.6 3.8 1 cam01/00050.jpg\n\n"
         "3 0.5 -0.5 0.5 -0.5 -0.3 1.4 4.2 2 cam02/00003.jpg\n\n"
         "4 1 0 0 0 0 0 0 3 aria01/00001.jpg\n\n";
}

std::string ColmapCalibrationCamerasText() {
  return "# Camera list\n1 PINHOLE 1920 1080 1000 1000 960 540\n2 OPENCV 1920 1080 1000 1001 950 530 0.1 -0.01 0.001 "
         "0.002\n"
         "3 OPENCV_FISHEYE 1920 1080 700 700 960 540 0.05 -0.01 0.002 -0.0003\n";
}

namespace {

// Pickle (protocol 2) of a dict str -> rows of floats (nested lists), what the EgoHumans readers
// accept in place of numpy arrays.
std::string PickleOfMatrices(const std::vector<std::pair<std::string, std::vector<std::vector<double>>>>& entries) {
  std::string out = "\x80\x02}(";  // PROTO 2, EMPTY_DICT, MARK
  auto le32 = [&](std::size_t v) {
    for (int i = 0; i < 4; ++i) out += static_cast<char>((v >> (8 * i)) & 0xff);
  };
  for (const auto& [key, rows] : entries) {
    out += 'X';  // BINUNICODE
    le32(key.size());
    out += key;
    out += "](";  // EMPTY_LIST, MARK
    for (const std::vector<double>& row : rows) {
      out += "](";
      for (const double v : row) {
        out += 'G';  // BINFLOAT, big endian
        const auto bits = std::bit_cast<std::uint64_t>(v);
        for (int i = 7; i >= 0; --i) out += static_cast<char>((bits >> (8 * i)) & 0xff);
      }
      out += 'e';  // APPENDS
    }
    out += 'e';
  }
  return out + "u.";  // SETITEMS, STOP
}

// np.save of an object: the NPY header of a 0-d object array, then the pickle of the object
// (np.load(allow_pickle=True) returns it as it is).
std::string ObjectNpy(const std::string& pickle) {
  std::string header = "{'descr': '|O', 'fortran_order': False, 'shape': (), }";
  while ((10 + header.size() + 1) % 64 != 0) header += ' ';
  header += '\n';
  std::string out = "\x93NUMPY\x01";
  out += '\0';
  out += static_cast<char>(header.size() & 0xff);
  out += static_cast<char>(header.size() >> 8);
  return out + header + pickle;
}

// colmap_from_aria_transforms.pkl: aria01 -> COLMAP a similarity (scale 1.5), aria02 a shift.
const std::string& EgohumansTransformsPickle() {
  static const std::string pickle =
      PickleOfMatrices({{"aria01", {{0, -1.5, 0, 0.3}, {1.5, 0, 0, -0.2}, {0, 0, 1.5, 1.1}, {0, 0, 0, 1}}},
                        {"aria02", {{1, 0, 0, 5}, {0, 1, 0, 5}, {0, 0, 1, 5}, {0, 0, 0, 1}}}});
  return pickle;
}

// processed_data/poses3d/00001.npy: aria01 standing near the origin (all 17 joints valid).
const std::string& EgohumansGtNpy() {
  static const std::string npy = [] {
    std::vector<std::vector<double>> joints;
    for (int j = 0; j < 17; ++j) joints.push_back({0.05 * std::sin(j), 0.04 * std::cos(j), 1.7 - 0.09 * j, 1.0});
    return ObjectNpy(PickleOfMatrices({{"aria01", joints}}));
  }();
  return npy;
}

// The EgoHumans files a target can fuzz; the others are the fixed companions above.
enum class EgoFile { kCameras, kImages, kTransforms, kManualCamera, kGt, kPoses2d };

// A sequence egohumans/01_tagging/001_tagging with one GT time stamp (00001), `bytes` as the file
// `fuzzed` and the companions as the others; the 2D cache is read (of cam01 only) when it is
// the fuzzed file.
// Every frame of every source converted and validated, as a run does.
void ReadAll(std::vector<std::unique_ptr<FrameSource>> sources) {
  for (const Sequence& sequence : MaterializeAll(std::move(sources))) ValidateSequence(sequence, sequence.name);
}

void ReadEgohumansWith(EgoFile fuzzed, std::span<const std::uint8_t> bytes) {
  const fs::path root = ScratchDir() / "egohumans";
  fs::remove_all(root);
  const std::string seq = "egohumans/01_tagging/001_tagging/";
  const std::string work = seq + "colmap/workplace/";
  auto write = [&](EgoFile file, const std::string& relative, const std::string& companion) {
    if (file == fuzzed) {
      WriteScratch(relative, bytes);
    } else {
      WriteScratch(relative, companion);
    }
  };
  write(EgoFile::kCameras, work + "cameras.txt", EgohumansCamerasText());
  write(EgoFile::kImages, work + "images.txt", EgohumansImagesText());
  write(EgoFile::kTransforms, work + "colmap_from_aria_transforms.pkl", EgohumansTransformsPickle());
  write(EgoFile::kGt, seq + "processed_data/poses3d/00001.npy", EgohumansGtNpy());
  std::map<std::string, std::string> params;
  if (fuzzed == EgoFile::kManualCamera) WriteScratch(work + "cam02.npy", bytes);
  if (fuzzed == EgoFile::kPoses2d) {
    WriteScratch(seq + "processed_data/poses2d/cam01/rgb/00001.npy", bytes);
    params = {{"cameras", "cam01"}, {"detections", "cache"}};
  }
  ReadAll(OpenEgohumans(DatasetRequest{"egohumans", root, params}));
}

// H3WB npz: the input holds train_data.npy and then metadata.npy; they are split at the second
// NPY magic and stored (uncompressed, with their CRC-32) into h3wb_train.npz as np.savez does,
// so that changed bytes reach the object trees instead of failing the CRC check.
std::string StoredZip(const std::vector<std::pair<std::string, std::string>>& members) {
  std::string out, central;
  auto le = [](std::string& to, std::uint64_t v, int n) {
    for (int i = 0; i < n; ++i) to += static_cast<char>((v >> (8 * i)) & 0xff);
  };
  for (const auto& [name, data] : members) {
    const auto crc = static_cast<std::uint32_t>(
        crc32(0L, reinterpret_cast<const Bytef*>(data.data()), static_cast<uInt>(data.size())));
    const std::size_t offset = out.size();
    le(out, 0x04034b50, 4);
    le(out, 20, 2);  // version needed
    le(out, 0, 2);   // flags
    le(out, 0, 2);   // stored
    le(out, 0, 4);   // time, date
    le(out, crc, 4);
    le(out, data.size(), 4);
    le(out, data.size(), 4);
    le(out, name.size(), 2);
    le(out, 0, 2);  // extra
    out += name;
    out += data;
    le(central, 0x02014b50, 4);
    le(central, 20, 2);
    le(central, 20, 2);
    le(central, 0, 2);
    le(central, 0, 2);
    le(central, 0, 4);
    le(central, crc, 4);
    le(central, data.size(), 4);
    le(central, data.size(), 4);
    le(central, name.size(), 2);
    le(central, 0, 2);  // extra
    le(central, 0, 2);  // comment
    le(central, 0, 2);  // disk
    le(central, 0, 2);  // internal attributes
    le(central, 0, 4);  // external attributes
    le(central, offset, 4);
    central += name;
  }
  const std::size_t central_offset = out.size();
  out += central;
  le(out, 0x06054b50, 4);
  le(out, 0, 2);
  le(out, 0, 2);
  le(out, members.size(), 2);
  le(out, members.size(), 2);
  le(out, central.size(), 4);
  le(out, central_offset, 4);
  le(out, 0, 2);  // comment
  return out;
}

void ReadH3wbNpz(std::span<const std::uint8_t> bytes) {
  const std::string text = Text(bytes);
  const std::size_t split = text.find("\x93NUMPY", 1);
  std::vector<std::pair<std::string, std::string>> members = {{"train_data.npy", text.substr(0, split)}};
  if (split != std::string::npos) members.emplace_back("metadata.npy", text.substr(split));
  const fs::path path = WriteScratch("h3wb_npz/h3wb_train.npz", StoredZip(members));
  ReadAll(OpenH3wb(DatasetRequest{"h3wb", path, {{"subjects", "S8"}, {"detections", "annotations"}}}));
}

// H3WB json: the input as 2Dto3D_train.json next to the fixed metadata.xml above; subject S8,
// the stored 2D read too.
void ReadH3wbJson(std::span<const std::uint8_t> bytes) {
  const fs::path root = ScratchDir() / "h3wb_json";
  fs::remove_all(root);
  WriteScratch("h3wb_json/metadata.xml", H36mMetadataXmlText());
  WriteScratch("h3wb_json/2Dto3D_train.json", bytes);
  ReadAll(OpenH3wb(DatasetRequest{"h3wb",
                                  root,
                                  {{"file", "2Dto3D_train.json"},
                                   {"cameras_file", "metadata.xml"},
                                   {"subjects", "S8"},
                                   {"detections", "annotations"}}}));
}

void ReadPanopticWith(const std::string& calibration, const std::string& bodies) {
  const fs::path root = ScratchDir() / "panoptic";
  fs::remove_all(root);
  WriteScratch("panoptic/seqA/calibration_seqA.json", calibration);
  WriteScratch("panoptic/seqA/hdPose3d_stage1_coco19/body3DScene_00000010.json", bodies);
  ReadAll(
      OpenPanoptic(DatasetRequest{"panoptic", root, {{"sequences", "seqA"}, {"cameras", "00_00"}, {"every", "1"}}}));
}

void ReadHdf5Cache(std::span<const std::uint8_t> bytes) {
  const fs::path path = WriteScratch("cache.h5", bytes);
  const Hdf5CacheContents contents = ProbeHdf5Cache(path);
  if (contents.sequences) ReadAll(OpenSequencesHdf5(path));
  if (contents.detections) ReadDetectionsHdf5(path);
}

// `bytes` as the file `name` read by ReadCalibration in `format` (warnings counted).
void ReadCalibrationWith(CalibrationFormat format, const std::string& name, std::span<const std::uint8_t> bytes) {
  InputWarnings warnings;
  ReadCalibration(WriteScratch(name, bytes), {.format = format}, &warnings);
}

// `bytes` as a sweep shard merged by `rpt merge` (into a scratch folder).
void MergeShard(std::span<const std::uint8_t> bytes) {
  const fs::path shard = WriteScratch("sweep-shard-1-of-1.json", bytes);
  CLI::App app;
  cli::RegisterMergeCommand(app);
  std::vector<std::string> args = {"merge", shard.string(), "--out", (ScratchDir() / "merged").string()};
  std::reverse(args.begin(), args.end());  // CLI11 parses a reversed vector
  app.parse(args);
}

// An `rpt eval` output folder read by `rpt report` (engine::ReadRecordedRun, the run's config and
// the page data without the input): the first byte picks the file the rest of `bytes` is
// (summary.json, config.json, run.json, predictions.json); the others are valid companions.
void ReadRunFolder(std::span<const std::uint8_t> bytes) {
  static const char* const kFiles[] = {"summary.json", "config.json", "run.json", "predictions.json"};
  const fs::path dir = ScratchDir() / "run";
  fs::create_directories(dir);
  WriteScratch("run/summary.json", std::string(R"({"mpjpe_mm": 50.5, "gt_persons": 2, "step_time_us_median": {"undistort": 3}})"));
  WriteScratch("run/config.json", std::string(R"({"filter": {"min_match_score": 0.9}})"));
  WriteScratch("run/run.json", std::string(R"({"run_id": "r", "argv": ["rpt", "eval", "--dataset", "synthetic"]})"));
  WriteScratch("run/predictions.json", std::string(R"({"joints": ["nose"], "frames": [{"id": "f0", "track_ids": [1],
    "persons": [[[0.1, 0.2, 1.5, 0.9]]]}]})"));
  WriteScratch("run/per_joint.csv", std::string("joint,mean_error_mm,pck100_pct,count,num_gt\nnose,10.5,90,4,4\n"));
  if (!bytes.empty()) WriteScratch(fs::path("run") / kFiles[bytes[0] % 4], bytes.subspan(1));
  const engine::RecordedRun run = engine::ReadRecordedRun(dir);
  engine::Config config;
  engine::LoadConfigFile(dir / "config.json", &config);
  std::vector<std::string> warnings;
  const nlohmann::ordered_json data =
      engine::BuildReportData(run, nullptr, "not re-loaded (fuzzing)", config.metrics, {}, &warnings);
  (void)data.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

// The live input's stream (rpt triangulate --follow) on two cameras cam_a and cam_b: every frame
// it hands out must be valid (an invalid one is a finding, not a refusal).
void ReadDetectionLines(std::span<const std::uint8_t> bytes) {
  std::vector<Camera> cameras(2);
  for (int c = 0; c < 2; ++c) {
    cameras[c].name = c == 0 ? "cam_a" : "cam_b";
    cameras[c].width = 640;
    cameras[c].height = 480;
    cameras[c].K << 500, 0, 320, 0, 500, 240, 0, 0, 1;
    cameras[c].t = Eigen::Vector3d(0.5 * c, 0, 4);
  }
  DetectionLinesOptions options;
  options.name = "fuzz";
  options.fps = 25;
  auto lines = std::make_unique<io::LineReader>(WriteScratch("lines.jsonl", bytes).string(), io::MaxInputBytes(), nullptr);
  const std::unique_ptr<FrameSource> source = OpenDetectionLines(cameras, std::move(lines), options, "cameras.json");
  SequenceFrame frame;
  while (source->Next(&frame)) {
    try {
      ValidateFrame(source->header(), frame, "fuzz");
    } catch (const InputError& e) {
      throw std::logic_error(std::string("detection lines handed out an invalid frame: ") + e.what());
    }
  }
}

std::vector<FuzzTarget> MakeTargets() {
  using B = std::span<const std::uint8_t>;
  return {
      {"config", "rpt configuration (--config)",
       [](B b) {
         engine::Config config;
         engine::LoadConfigFile(WriteScratch("config.json", b), &config);
       }},
      {"thresholds", "rpt check thresholds file (--thresholds)",
       [](B b) { engine::ReadThresholdsFile(WriteScratch("thresholds.json", b).string()); }},
      {"sweep_list", "rpt sweep configuration list (--list)",
       [](B b) { engine::ReadSweepList(WriteScratch("sweep.json", b).string()); }},
      {"sweep_shard", "rpt sweep shard merged by rpt merge", MergeShard},
      {"run_folder", "rpt eval output folder read by rpt report (summary, config, run, predictions JSON)",
       ReadRunFolder},
      {"labels", "generic JSON labels (rpt / skelda)",
       [](B b) { ReadAll(OpenLabels(WriteScratch("labels.json", b))); }},
      {"detections_json", "generic JSON detections",
       [](B b) { ReadGenericDetections(WriteScratch("detections.json", b)); }},
      {"detection_lines", "detection lines of the live input (rpt triangulate --follow)", ReadDetectionLines},
      {"coco", "COCO keypoint result list (MVOR image ids)",
       [](B b) { ReadCocoDetections(WriteScratch("results.json", b)); }},
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
       [](B b) {
         ReadVoxelPoseDetections(WriteScratch("pred.pkl", b), {{"0", "1"}, "shelf"});
       }},
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
      {"fourda_skeletons", "4D-Association skeleton text (gt.txt)",
       [](B b) { ParseFourDaSkeletons(Text(b), "gt.txt"); }},
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
         ReadAll(OpenMvor(DatasetRequest{"mvor", root, {{"days", "1"}, {"detections", "none"}}}));
       }},
      {"h36m_metadata_xml", "Human3.6M metadata.xml cameras",
       [](B b) { ReadHuman36mCameras(WriteScratch("metadata.xml", b), "S1", DistortionModel::kOpenCV, nullptr); }},
      {"h3wb_json", "H3WB 2Dto3D_*.json / RGBto3D_*.json (cameras from a fixed metadata.xml)", ReadH3wbJson},
      {"h3wb_npz",
       "H3WB h3wb_train.npz new format: its members train_data.npy then metadata.npy (the target stores them into the "
       "npz)",
       ReadH3wbNpz},
      {"egohumans_cameras", "EgoHumans colmap/workplace/cameras.txt (exo cameras: size, model, naming by image)",
       [](B b) { ReadEgohumansWith(EgoFile::kCameras, b); }},
      {"egohumans_images", "EgoHumans colmap/workplace/images.txt (exo poses: camXX/<time stamp>.jpg nearest the GT)",
       [](B b) { ReadEgohumansWith(EgoFile::kImages, b); }},
      {"egohumans_transforms", "EgoHumans colmap_from_aria_transforms.pkl (aria -> COLMAP similarities)",
       [](B b) { ReadEgohumansWith(EgoFile::kTransforms, b); }},
      {"egohumans_camera_npy", "EgoHumans manual exo calibration camXX.npy (4x4 COLMAP -> camera)",
       [](B b) { ReadEgohumansWith(EgoFile::kManualCamera, b); }},
      {"egohumans_gt", "EgoHumans processed_data/poses3d/<time stamp>.npy (aria name -> (17, 4))",
       [](B b) { ReadEgohumansWith(EgoFile::kGt, b); }},
      {"calibration_json", "our cameras JSON ({\"cameras\": [...]}) through ReadCalibration",
       [](B b) { ReadCalibrationWith(CalibrationFormat::kJson, "cameras.json", b); }},
      {"calibration_opencv",
       "OpenCV FileStorage camera (calibrateCamera / stereo / ROS keys; YAML, XML or JSON by content)",
       [](B b) { ReadCalibrationWith(CalibrationFormat::kOpenCV, "camera.yml", b); }},
      {"calibration_easymocap", "EasyMocap cameras (intri.yml and extri.yml keys in one file)",
       [](B b) { ReadCalibrationWith(CalibrationFormat::kEasyMocap, "cameras.yml", b); }},
      {"calibration_toml", "Pose2Sim / anipose camera group .toml",
       [](B b) { ReadCalibrationWith(CalibrationFormat::kToml, "calib.toml", b); }},
      {"calibration_colmap", "COLMAP images.txt read as a calibration (with a fixed cameras.txt)",
       [](B b) {
         fs::remove_all(ScratchDir() / "colmap");
         WriteScratch("colmap/cameras.txt", ColmapCalibrationCamerasText());
         ReadCalibrationWith(CalibrationFormat::kColmap, "colmap/images.txt", b);
       }},
      {"egohumans_poses2d",
       "EgoHumans 2D cache processed_data/poses2d/<cam>/rgb/<time stamp>.npy (list of dicts, keypoints (133, 3))",
       [](B b) { ReadEgohumansWith(EgoFile::kPoses2d, b); }},
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
