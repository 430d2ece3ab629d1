// SPDX-License-Identifier: MIT
// `rpt cameras show FILE` and `rpt cameras convert IN OUT`: a calibration file of another tool
// read into our cameras (datasets/calibration/calibration.h; every format of docs/cameras.md),
// what was read printed, and the cameras written in another format.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "cli/field_options.h"
#include "cli/input_options.h"
#include "core/printable_text.h"
#include "datasets/camera_plausibility.h"
#include "datasets/calibration/calibration.h"
#include "datasets/io/staged_output.h"

namespace rpt::cli {
namespace {

namespace fs = std::filesystem;

void PrintCameras(const fs::path& path, const Calibration& calibration) {
  std::printf("%s: %zu cameras\n", PrintableText(path.string()).c_str(), calibration.cameras.size());
  for (const std::string& line : calibration.description.Lines()) std::printf("  %s\n", PrintableText(line).c_str());
  // The widest angle to another camera where their views cross: below 10 degrees depth is poorly
  // fixed (datasets/camera_plausibility.h); "-" when no other camera's view crosses this one's.
  const std::vector<double> widest = WidestCrossingAnglesDeg(calibration.cameras);
  std::printf("\n  %-16s %11s  %-9s %26s  %17s  %20s  %s\n", "camera", "image (px)", "lens", "centre x y z (m)",
              "focal fx fy (px)", "principal point (px)", "widest angle (deg)");
  for (std::size_t i = 0; i < calibration.cameras.size(); ++i) {
    const Camera& c = calibration.cameras[i];
    const std::string size = std::to_string(c.width) + "x" + std::to_string(c.height);
    const Eigen::Vector3d centre = c.Center();
    char angle[16] = "-";
    if (widest[i] >= 0) std::snprintf(angle, sizeof(angle), "%.0f", widest[i]);
    std::printf("  %-16s %11s  %-9s %8.3f %8.3f %8.3f  %8.1f %8.1f  %8.1f %8.1f  %18s\n",
                PrintableText(c.name, LineBreaks::kEscape).c_str(), size.c_str(), DistortionModelName(c.model),
                centre.x(), centre.y(), centre.z(), c.K(0, 0), c.K(1, 1), c.K(0, 2), c.K(1, 2), angle);
  }
  std::printf("\n  widest angle: between the camera's rays and another camera's where their views cross, the "
              "widest over the other cameras (under %.0f: depth along its view is poorly fixed)\n",
              kMinPlausibleViewAngleDeg);
}

}  // namespace

void RegisterCamerasCommand(CLI::App& app) {
  CLI::App* cameras = app.add_subcommand("cameras", "Read a calibration file of another tool: show it or convert it");
  cameras->require_subcommand(1);

  CLI::App* show = cameras->add_subcommand(
      "show", "Print what a calibration file holds: format and conventions read, per camera image size, lens, centre");
  auto show_path = std::make_shared<std::string>();
  show->add_option("FILE", *show_path, "calibration file or folder (docs/cameras.md)")->required();
  auto show_read = std::make_shared<FieldOptions<CalibrationReadOptions>>(show, "", "reading: ");
  show->callback([show_path, show_read] {
    InputWarnings warnings;
    const Calibration calibration = ReadCalibration(*show_path, show_read->Parse(), &warnings);
    PrintCameras(*show_path, calibration);
    PrintInputWarnings(warnings);
  });

  CLI::App* convert = cameras->add_subcommand(
      "convert", "Convert a calibration file: IN (any format read) to OUT (json, opencv .yml/.xml, easymocap, toml)");
  auto in = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  convert->add_option("IN", *in, "calibration file or folder read")->required();
  convert->add_option("OUT", *out, "file written; its name chooses the format unless --out-format is given")->required();
  auto convert_read = std::make_shared<FieldOptions<CalibrationReadOptions>>(convert, "", "reading: ");
  auto convert_write = std::make_shared<FieldOptions<CalibrationWriteOptions>>(convert, "out-", "writing: ");
  convert->callback([in, out, convert_read, convert_write] {
    InputWarnings warnings;
    const Calibration calibration = ReadCalibration(*in, convert_read->Parse(), &warnings);
    PrintInputWarnings(warnings);
    InputWarnings written;
    io::ParentFolders folders(*out);  // removed again when the write fails
    WriteCalibration(*out, calibration.cameras, convert_write->Parse(), &written);
    folders.Keep();
    PrintInputWarnings(written);
    std::printf("%s -> %s: %zu cameras\n", PrintableText(*in).c_str(), PrintableText(*out).c_str(),
                calibration.cameras.size());
  });
}

}  // namespace rpt::cli
