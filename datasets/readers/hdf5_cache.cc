// SPDX-License-Identifier: MIT
#include "datasets/readers/hdf5_cache.h"

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <numeric>
#include <sstream>
#include <unordered_map>
#include <unordered_set>

#include "core/errors.h"
#include "core/printable_text.h"
#include "datasets/io/hdf5_file.h"
#include "datasets/input_warnings.h"
#include "datasets/readers/generic_common.h"
#include "datasets/readers/generic_detections.h"

namespace rpt {
namespace {

// Version 4 (written): version 3's layout; a camera a frame of /detections does not list has no
// data in that frame (Detections::unlisted_cameras_unavailable; cameras that saw nobody are listed
// with no persons). Version 3 (read): every dataset carries the CRC-32 of its values
// (io::NumbersCrc, io::StringsCrc), and the groups /sequences and /sequences/<i> the CRC-32 of
// their attributes (AttributesCrc), all checked on reading; an unlisted camera saw nobody.
// Version 2 (read): dataset checksums only. Version 1 (read): the same layout without checksums.
constexpr int kVersion = 4;
constexpr int kVersionWithAttributeChecksums = 3;
constexpr int kVersionWithoutAttributeChecksums = 2;
constexpr int kVersionWithoutChecksums = 1;
constexpr const char* kDetectionsFormat = "rpt-detections";
constexpr const char* kSequencesFormat = "rpt-sequences";

using io::Hdf5Id;
using io::Hdf5Quiet;
using io::Hdf5Reader;
using io::Hdf5Writer;
using io::ShapeText;

// The checksum a group's attributes carry (attribute "crc32" of the group, version 3): the group's
// string attributes as io::StringsCrc continues over them, then its numbers as io::NumbersCrc
// does (little-endian doubles). /sequences: its count; /sequences/<i>: its name and fps.
std::uint32_t AttributesCrc(const std::vector<std::string>& strings, const std::vector<double>& numbers) {
  std::uint32_t crc = io::StringsCrc(strings);
  for (const double number : numbers) crc = io::Crc32(crc, std::string_view(reinterpret_cast<const char*>(&number), sizeof number));
  return crc;
}

// Returns the file's format version (1 to 4) after checking its tag.
int CheckFormat(io::Hdf5Reader& reader, hid_t group, const std::string& place, const std::string& format) {
  const std::string found = reader.HasAttribute(group, place, "format") ? reader.StringAttribute(group, place, "format") : "";
  if (found != format) {
    // A damaged file can hold any bytes there (even a heap address HDF5 returned): quoted inside the
    // one-line message, newlines and tabs included, escaped.
    reader.Fail(place, "attribute format is " + QuoteName(found) + ", expected " + QuoteName(format) +
                           " (not written by rpt?)");
  }
  const double version = reader.NumberAttribute(group, place, "version");
  if (version != kVersion && version != kVersionWithAttributeChecksums && version != kVersionWithoutAttributeChecksums &&
      version != kVersionWithoutChecksums) {
    reader.Fail(place, "format version " + std::to_string(version) + " is not supported (this build reads versions " +
                    std::to_string(kVersionWithoutChecksums) + " to " + std::to_string(kVersion) + ")");
  }
  // rpt writes version 4 (3 before unlisted cameras meant no data, 2 before its attributes had
  // checksums); version 1 is the format other tools (and rpt before checksums) write.
  if (version != kVersionWithoutChecksums) reader.RequireChecksums();
  return static_cast<int>(version);
}

// Offsets: offsets[0] = 0, non-decreasing, offsets.back() = total.
void CheckOffsets(const io::Hdf5Reader& reader, const std::vector<std::int64_t>& offsets, const std::string& name, const std::string& total_what,
                  std::int64_t total) {
  if (offsets.empty() || offsets.front() != 0) reader.Fail(name, "must start with 0");
  for (size_t i = 1; i < offsets.size(); ++i) {
    if (offsets[i] < offsets[i - 1]) reader.Fail(name, "decreases at element " + std::to_string(i));
  }
  if (offsets.back() != total) {
    reader.Fail(name, "ends at " + std::to_string(offsets.back()) + " but " + total_what + " has " + std::to_string(total));
  }
}

std::vector<long long> Shape(std::initializer_list<long long> dims) { return dims; }

}  // namespace

void SkipHdf5CleanupAtExit() { io::SkipHdf5CleanupAtExit(); }

// -----------------------------------------------------------------------------------------------
// Detections

void WriteDetectionsHdf5(const std::filesystem::path& path, const Detections& given, const Hdf5WriteOptions& options) {
  // Version 4: an unlisted camera has no data; cameras that saw nobody are listed with no persons.
  const std::unique_ptr<Detections> normalised = WithUnlistedCamerasUnavailable(given);
  const Detections& detections = normalised ? *normalised : given;
  const Hdf5Quiet quiet;
  ValidateDetections(detections, path.string() + ": cannot write");
  const size_t num_joints = detections.joints.size();

  std::vector<std::string> cameras;
  std::unordered_map<std::string, std::int32_t> camera_index;
  std::vector<std::string> frame_ids;
  std::vector<std::int64_t> view_offsets = {0};
  std::vector<std::int32_t> view_cameras;
  std::vector<std::int64_t> person_offsets = {0};
  size_t total_values = 0;
  for (const FrameDetections& frame : detections.frames) {
    frame_ids.push_back(frame.frame_id);
    for (size_t v = 0; v < frame.views.size(); ++v) {
      const auto [it, fresh] = camera_index.emplace(frame.cameras[v], static_cast<std::int32_t>(cameras.size()));
      if (fresh) cameras.push_back(frame.cameras[v]);
      view_cameras.push_back(it->second);
      person_offsets.push_back(person_offsets.back() + frame.views[v].num_persons());
      total_values += frame.views[v].data.size();
    }
    view_offsets.push_back(static_cast<std::int64_t>(view_cameras.size()));
  }
  const std::vector<hsize_t> keypoint_dims = {static_cast<hsize_t>(person_offsets.back()), num_joints, 3};

  Hdf5Writer writer(path, options.add_to_existing);
  const std::string name = "/detections";
  Hdf5Id group = writer.Group(name);
  writer.StringAttribute(group.get(), name, "format", kDetectionsFormat);
  writer.NumberAttribute(group.get(), name, "version", H5T_STD_I32LE, H5T_NATIVE_INT, kVersion);
  writer.Strings(group.get(), name, "joints", detections.joints);
  writer.Strings(group.get(), name, "cameras", cameras);
  writer.Strings(group.get(), name, "frame_ids", frame_ids);
  writer.Int64s(group.get(), name, "view_offsets", view_offsets);
  writer.Int32s(group.get(), name, "view_cameras", {view_cameras.size()}, view_cameras);
  writer.Int64s(group.get(), name, "person_offsets", person_offsets);
  // The frames' times (generic JSON's "time"; NaN = unknown), when any is known: a cache of timed
  // detections triangulated without labels tracked nothing.
  if (std::any_of(detections.frames.begin(), detections.frames.end(),
                  [](const FrameDetections& frame) { return std::isfinite(frame.time_s); })) {
    std::vector<double> times;
    for (const FrameDetections& frame : detections.frames) times.push_back(frame.time_s);
    writer.Doubles(group.get(), name, "times", {times.size()}, times);
  }
  if (options.float64) {
    std::vector<double> values;
    values.reserve(total_values);
    for (const FrameDetections& frame : detections.frames) {
      for (const Poses2D& view : frame.views) values.insert(values.end(), view.data.begin(), view.data.end());
    }
    writer.Numbers(group.get(), name, "keypoints", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, keypoint_dims, values.data());
  } else {
    std::vector<float> values;
    values.reserve(total_values);
    for (const FrameDetections& frame : detections.frames) {
      for (const Poses2D& view : frame.views) {
        for (double d : view.data) values.push_back(static_cast<float>(d));
      }
    }
    writer.Numbers(group.get(), name, "keypoints", H5T_IEEE_F32LE, H5T_NATIVE_FLOAT, keypoint_dims, values.data());
  }
  group = Hdf5Id();
  writer.Close();
}

namespace {

// Reads [P, J, 3] keypoints in their stored precision.
template <typename T>
void FillViews(const std::vector<T>& values, const Hdf5Reader& reader, const std::string& name, Detections* detections,
               const std::vector<std::int64_t>& person_offsets) {
  const size_t num_joints = detections->joints.size();
  const size_t stride = 3 * num_joints;
  size_t view_index = 0;
  for (FrameDetections& frame : detections->frames) {
    for (size_t v = 0; v < frame.views.size(); ++v, ++view_index) {
      const size_t begin = static_cast<size_t>(person_offsets[view_index]) * stride;
      const size_t end = static_cast<size_t>(person_offsets[view_index + 1]) * stride;
      Poses2D& view = frame.views[v];
      view.Clear(static_cast<int>(num_joints));
      view.data.resize(end - begin);
      for (size_t i = begin; i < end; i += 3) {
        const double x = values[i], y = values[i + 1];
        // "<file>: /detections/keypoints: person 3 (frame 'f', camera 'c'), joint 'nose'" for messages.
        const auto where = [&] {
          return reader.source() + ": " + name + ": person " + std::to_string(i / stride) + " (frame '" +
                 frame.frame_id + "', camera " + QuoteName(frame.cameras[v]) + "), joint '" +
                 detections->joints[(i % stride) / 3] + "'";
        };
        if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(static_cast<double>(values[i + 2]))) {
          throw InputError(where() + ": NaN or infinite value");
        }
        view.data[i - begin] = x;
        view.data[i - begin + 1] = y;
        view.data[i - begin + 2] = AcceptScore(values[i + 2], reader.source(), &detections->warnings, where);
      }
    }
  }
}

}  // namespace

Detections ReadDetectionsHdf5(const std::filesystem::path& path) {
  const Hdf5Quiet quiet;
  Hdf5Reader reader(path);
  const std::string name = "/detections";
  if (!reader.Exists(name)) {
    reader.Fail(name, std::string("missing: no detections in this file") +
                          (reader.Exists("/sequences") ? " (it holds labels only)" : " (not an rpt cache?)"));
  }
  Hdf5Id group = reader.OpenGroup(name, "detections");
  const int version = CheckFormat(reader, group.get(), name, kDetectionsFormat);

  Detections detections;
  detections.unlisted_cameras_unavailable = version >= kVersion;
  detections.joints = reader.Strings(name + "/joints");
  CheckJointNames(detections.joints, reader.source() + ": " + name + "/joints");
  const std::vector<std::string> cameras = reader.Strings(name + "/cameras");
  for (size_t c = 0; c < cameras.size(); ++c) {
    if (cameras[c].empty()) reader.Fail(name + "/cameras", "camera " + std::to_string(c) + " has an empty name");
  }
  const std::vector<std::string> frame_ids = reader.Strings(name + "/frame_ids");
  const long long num_frames = static_cast<long long>(frame_ids.size());
  const std::vector<std::int64_t> view_offsets =
      reader.Int64s(name + "/view_offsets", Shape({num_frames + 1}), "frames + 1");
  const std::vector<std::int32_t> view_cameras = reader.Numbers<std::int32_t>(name + "/view_cameras", H5T_NATIVE_INT32, Shape({-1}));
  CheckOffsets(reader, view_offsets, name + "/view_offsets", name + "/view_cameras", static_cast<std::int64_t>(view_cameras.size()));
  const long long num_views = static_cast<long long>(view_cameras.size());
  const std::vector<std::int64_t> person_offsets =
      reader.Int64s(name + "/person_offsets", Shape({num_views + 1}), "views + 1");

  const std::string keypoints_name = name + "/keypoints";
  Hdf5Id keypoints = reader.OpenDataset(keypoints_name);
  const std::vector<hsize_t> dims = reader.CheckShape(
      keypoints.get(), keypoints_name, Shape({-1, static_cast<long long>(detections.joints.size()), 3}),
      "persons x joints x [u, v, score]");
  CheckOffsets(reader, person_offsets, name + "/person_offsets", keypoints_name, static_cast<std::int64_t>(dims[0]));

  // Optional: the frames' times in seconds (NaN = unknown).
  std::vector<double> times;
  if (reader.Exists(name + "/times")) {
    times = reader.Numbers<double>(name + "/times", H5T_NATIVE_DOUBLE, Shape({num_frames}));
    for (size_t f = 0; f < times.size(); ++f) {
      if (std::isinf(times[f])) reader.Fail(name + "/times", "element " + std::to_string(f) + " is infinite");
    }
  }
  std::unordered_set<std::string> seen_ids;
  detections.frames.resize(frame_ids.size());
  for (size_t f = 0; f < frame_ids.size(); ++f) {
    FrameDetections& frame = detections.frames[f];
    frame.frame_id = frame_ids[f];
    if (!times.empty()) frame.time_s = times[f];
    if (frame.frame_id.empty()) reader.Fail(name + "/frame_ids", "frame " + std::to_string(f) + " has an empty id");
    if (!seen_ids.insert(frame.frame_id).second) reader.Fail(name + "/frame_ids", "frame id " + QuoteName(frame.frame_id) + " appears twice");
    for (std::int64_t v = view_offsets[f]; v < view_offsets[f + 1]; ++v) {
      const std::int32_t c = view_cameras[static_cast<size_t>(v)];
      if (c < 0 || static_cast<size_t>(c) >= cameras.size()) {
        reader.Fail(name + "/view_cameras", "element " + std::to_string(v) + " is " + std::to_string(c) + ", outside 0.." +
                                                std::to_string(static_cast<long long>(cameras.size()) - 1));
      }
      if (std::find(frame.cameras.begin(), frame.cameras.end(), cameras[c]) != frame.cameras.end()) {
        reader.Fail(name + "/view_cameras", "frame " + QuoteName(frame.frame_id) + " has camera " + QuoteName(cameras[c]) + " twice");
      }
      frame.cameras.push_back(cameras[c]);
    }
    frame.views.resize(frame.cameras.size());
  }

  Hdf5Id type(H5Dget_type(keypoints.get()), H5Tclose);
  if (!type.valid() || H5Tget_class(type.get()) != H5T_FLOAT || !Hdf5Reader::IsStandardNumber(type.get())) {
    reader.Fail(keypoints_name, "expected IEEE floating-point values");
  }
  const size_t count = reader.Count(dims, keypoints_name);
  const bool single = H5Tget_size(type.get()) <= 4;
  reader.PrepareRead(keypoints.get(), keypoints_name, count, H5Tget_size(type.get()), single ? sizeof(float) : sizeof(double));
  if (single) {
    std::vector<float> values(count);
    if (count > 0 && H5Dread(keypoints.get(), H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0) {
      reader.Fail(keypoints_name, "read failed (damaged file?)");
    }
    reader.VerifyChecksum(keypoints.get(), keypoints_name, io::NumbersCrc(values.data(), values.size()));
    FillViews(values, reader, keypoints_name, &detections, person_offsets);
  } else {
    std::vector<double> values(count);
    if (count > 0 && H5Dread(keypoints.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0) {
      reader.Fail(keypoints_name, "read failed (damaged file?)");
    }
    reader.VerifyChecksum(keypoints.get(), keypoints_name, io::NumbersCrc(values.data(), values.size()));
    FillViews(values, reader, keypoints_name, &detections, person_offsets);
  }
  return detections;
}

// -----------------------------------------------------------------------------------------------
// Sequences

void WriteSequencesHdf5(const std::filesystem::path& path, const std::vector<Sequence>& sequences,
                        const Hdf5WriteOptions& options) {
  const Hdf5Quiet quiet;
  for (const Sequence& sequence : sequences) {
    Sequence without_views = sequence;  // views are not stored; validate cameras and GT only
    for (SequenceFrame& frame : without_views.frames) frame.views.clear();
    ValidateSequence(without_views, path.string() + ": cannot write sequence " + QuoteName(sequence.name));
    CheckJointNames(sequence.gt_joints, path.string() + ": cannot write sequence " + QuoteName(sequence.name));
  }
  Hdf5Writer writer(path, options.add_to_existing);
  Hdf5Id root = writer.Group("/sequences");
  writer.StringAttribute(root.get(), "/sequences", "format", kSequencesFormat);
  writer.NumberAttribute(root.get(), "/sequences", "version", H5T_STD_I32LE, H5T_NATIVE_INT, kVersion);
  writer.NumberAttribute(root.get(), "/sequences", "count", H5T_STD_I64LE, H5T_NATIVE_INT64,
                         static_cast<std::int64_t>(sequences.size()));
  writer.Checksum(root.get(), "/sequences", AttributesCrc({}, {static_cast<double>(sequences.size())}));
  for (size_t s = 0; s < sequences.size(); ++s) {
    const Sequence& sequence = sequences[s];
    const std::string name = "/sequences/" + std::to_string(s);
    Hdf5Id group = writer.Group(name);
    const hid_t g = group.get();
    writer.StringAttribute(g, name, "name", sequence.name);
    writer.NumberAttribute(g, name, "fps", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, sequence.fps);
    writer.Checksum(g, name, AttributesCrc({sequence.name}, {sequence.fps}));
    const Room& room = sequence.room;
    writer.Doubles(g, name, "room_center", {3}, {room.center_m.x(), room.center_m.y(), room.center_m.z()});
    writer.Doubles(g, name, "room_size", {3}, {room.size_m.x(), room.size_m.y(), room.size_m.z()});

    const hsize_t num_cameras = sequence.cameras.size();
    std::vector<std::string> names, models;
    std::vector<std::int32_t> sizes;
    std::vector<double> K, dist, R, t;
    for (const Camera& camera : sequence.cameras) {
      names.push_back(camera.name);
      models.push_back(DistortionModelName(camera.model));
      sizes.push_back(camera.width);
      sizes.push_back(camera.height);
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) {
          K.push_back(camera.K(r, c));
          R.push_back(camera.R(r, c));
        }
        t.push_back(camera.t[r]);
      }
      dist.insert(dist.end(), camera.dist.begin(), camera.dist.end());
    }
    writer.Strings(g, name, "camera_names", names);
    writer.Strings(g, name, "camera_models", models);
    writer.Int32s(g, name, "camera_image_size", {num_cameras, 2}, sizes);
    writer.Doubles(g, name, "camera_K", {num_cameras, 3, 3}, K);
    writer.Doubles(g, name, "camera_dist", {num_cameras, 5}, dist);
    writer.Doubles(g, name, "camera_R", {num_cameras, 3, 3}, R);
    writer.Doubles(g, name, "camera_t", {num_cameras, 3}, t);

    writer.Strings(g, name, "gt_joints", sequence.gt_joints);
    std::vector<std::string> frame_ids;
    std::vector<double> timestamps, poses;
    std::vector<std::int64_t> offsets = {0};
    std::vector<std::int32_t> track_ids;
    for (const SequenceFrame& frame : sequence.frames) {
      frame_ids.push_back(frame.id);
      timestamps.push_back(frame.timestamp_s);
      offsets.push_back(offsets.back() + frame.gt.num_persons());
      poses.insert(poses.end(), frame.gt.data.begin(), frame.gt.data.end());
      track_ids.insert(track_ids.end(), frame.gt.track_ids.begin(), frame.gt.track_ids.end());
    }
    writer.Strings(g, name, "frame_ids", frame_ids);
    writer.Doubles(g, name, "timestamps", {frame_ids.size()}, timestamps);
    writer.Int64s(g, name, "gt_offsets", offsets);
    writer.Doubles(g, name, "gt_poses", {static_cast<hsize_t>(offsets.back()), sequence.gt_joints.size(), 4}, poses);
    writer.Int32s(g, name, "gt_track_ids", {track_ids.size()}, track_ids);
  }
  root = Hdf5Id();
  writer.Close();
}

std::vector<std::unique_ptr<FrameSource>> OpenSequencesHdf5(const std::filesystem::path& path) {
  const Hdf5Quiet quiet;
  Hdf5Reader reader(path);
  if (!reader.Exists("/sequences")) {
    reader.Fail("/sequences", std::string("missing: no labels in this file") +
                                  (reader.Exists("/detections") ? " (it holds detections only)" : " (not an rpt cache?)"));
  }
  Hdf5Id root = reader.OpenGroup("/sequences", "labels");
  const int version = CheckFormat(reader, root.get(), "/sequences", kSequencesFormat);
  // Version 3: a group's attributes are compared with the checksum the group carries.
  const auto verify_attributes = [&](hid_t group, const std::string& place, std::uint32_t crc) {
    if (version >= kVersionWithAttributeChecksums) reader.VerifyChecksum(group, place, crc, "attributes");
  };
  const double count = reader.NumberAttribute(root.get(), "/sequences", "count");
  verify_attributes(root.get(), "/sequences", AttributesCrc({}, {count}));
  if (!(count >= 0) || count != std::floor(count) || count > 1e7) reader.Fail("/sequences", "bad attribute count");

  std::vector<std::unique_ptr<FrameSource>> sources;
  for (int s = 0; s < static_cast<int>(count); ++s) {
    const std::string name = "/sequences/" + std::to_string(s);
    Hdf5Id group = reader.OpenGroup(name, "sequence " + std::to_string(s) + " of " + std::to_string(static_cast<int>(count)));
    SequenceHeader sequence;
    InputWarnings warnings;
    sequence.name = reader.StringAttribute(group.get(), name, "name");
    sequence.fps = reader.NumberAttribute(group.get(), name, "fps");
    verify_attributes(group.get(), name, AttributesCrc({sequence.name}, {sequence.fps}));
    if (!std::isfinite(sequence.fps) || sequence.fps < 0) reader.Fail(name, "attribute fps is not a non-negative number");
    const auto center = reader.Doubles(name + "/room_center", Shape({3}));
    const auto size = reader.Doubles(name + "/room_size", Shape({3}));
    sequence.room.center_m = Eigen::Vector3d(center[0], center[1], center[2]);
    sequence.room.size_m = Eigen::Vector3d(size[0], size[1], size[2]);

    const std::vector<std::string> names = reader.Strings(name + "/camera_names");
    const long long C = static_cast<long long>(names.size());
    const std::vector<std::string> models = reader.Strings(name + "/camera_models", C);
    const auto sizes = reader.Numbers<std::int32_t>(name + "/camera_image_size", H5T_NATIVE_INT32, Shape({C, 2}));
    const auto K = reader.Doubles(name + "/camera_K", Shape({C, 3, 3}));
    const auto dist = reader.Doubles(name + "/camera_dist", Shape({C, 5}));
    const auto R = reader.Doubles(name + "/camera_R", Shape({C, 3, 3}));
    const auto t = reader.Doubles(name + "/camera_t", Shape({C, 3}));
    for (long long c = 0; c < C; ++c) {
      Camera& camera = sequence.cameras.emplace_back();
      camera.name = names[c];
      const std::string& model = models[c];
      if (model == "none") {
        camera.model = DistortionModel::kNone;
      } else if (model == "opencv") {
        camera.model = DistortionModel::kOpenCV;
      } else if (model == "h36m") {
        camera.model = DistortionModel::kH36M;
      } else if (model == "fisheye") {
        camera.model = DistortionModel::kFisheye;
      } else {
        reader.Fail(name + "/camera_models", "camera " + std::to_string(c) + ": unknown model '" +
                                                 PrintableText(model, LineBreaks::kEscape) + "'");
      }
      camera.width = sizes[2 * c];
      camera.height = sizes[2 * c + 1];
      for (int r = 0; r < 3; ++r) {
        for (int k = 0; k < 3; ++k) {
          camera.K(r, k) = K[9 * c + 3 * r + k];
          camera.R(r, k) = R[9 * c + 3 * r + k];
        }
        camera.t[r] = t[3 * c + r];
      }
      camera.R = AcceptRotation(
          camera.R, reader.source(),
          reader.source() + ": " + name + "/camera_R: camera " + std::to_string(c) + " (" + QuoteName(camera.name) + ")",
          &warnings);
      std::copy(dist.begin() + 5 * c, dist.begin() + 5 * c + 5, camera.dist.begin());
    }

    sequence.gt_joints = reader.Strings(name + "/gt_joints");
    CheckJointNames(sequence.gt_joints, reader.source() + ": " + name + "/gt_joints");
    const long long J = static_cast<long long>(sequence.gt_joints.size());
    std::vector<std::string> frame_ids = reader.Strings(name + "/frame_ids");
    const long long F = static_cast<long long>(frame_ids.size());
    // NaN = unknown time (labels without times); infinities are errors.
    auto timestamps = reader.Numbers<double>(name + "/timestamps", H5T_NATIVE_DOUBLE, Shape({F}));
    long unknown_times = 0;
    for (size_t f = 0; f < timestamps.size(); ++f) {
      if (std::isinf(timestamps[f])) reader.Fail(name + "/timestamps", "element " + std::to_string(f) + " is infinite");
      unknown_times += std::isnan(timestamps[f]) ? 1 : 0;
    }
    warnings.AddMissing(reader.source(),
                        "frames with unknown times (NaN timestamps, e.g. of labels without times): nothing is carried "
                        "from one frame to the next; convert labels that have times to give them",
                        unknown_times);
    // The arrays stay as read; each frame is cut out of them when it is pulled.
    struct Arrays {
      std::vector<std::string> frame_ids;
      std::vector<double> timestamps;
      std::vector<std::int64_t> offsets;
      std::vector<double> poses;
      std::vector<std::int32_t> track_ids;
    };
    auto arrays = std::make_shared<Arrays>();
    arrays->frame_ids = std::move(frame_ids);
    arrays->timestamps = std::move(timestamps);
    arrays->offsets = reader.Int64s(name + "/gt_offsets", Shape({F + 1}), "frames + 1");
    arrays->poses = reader.Doubles(name + "/gt_poses", Shape({-1, J, 4}), "persons x joints x [x, y, z, score]");
    const long long P = static_cast<long long>(J > 0 ? arrays->poses.size() / (4 * J) : 0);
    CheckOffsets(reader, arrays->offsets, name + "/gt_offsets", name + "/gt_poses", P);
    arrays->track_ids = reader.Numbers<std::int32_t>(name + "/gt_track_ids", H5T_NATIVE_INT32, Shape({P}));
    auto convert = [arrays, J](size_t f, SequenceFrame* frame, InputWarnings*) {
      const Arrays& a = *arrays;
      frame->id = a.frame_ids[f];
      frame->timestamp_s = a.timestamps[f];
      frame->gt.Clear(static_cast<int>(J));
      frame->gt.data.assign(a.poses.begin() + a.offsets[f] * 4 * J, a.poses.begin() + a.offsets[f + 1] * 4 * J);
      frame->gt.track_ids.assign(a.track_ids.begin() + a.offsets[f], a.track_ids.begin() + a.offsets[f + 1]);
    };
    sources.push_back(std::make_unique<IndexedFrameSource>(std::move(sequence), static_cast<size_t>(F),
                                                           std::move(convert), std::move(warnings)));
  }
  return sources;
}

Hdf5CacheContents ProbeHdf5Cache(const std::filesystem::path& path) {
  const Hdf5Quiet quiet;
  const Hdf5Reader reader(path);
  Hdf5CacheContents contents;
  contents.detections = reader.Exists("/detections");
  contents.sequences = reader.Exists("/sequences");
  return contents;
}

}  // namespace rpt
