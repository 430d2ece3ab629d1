// SPDX-License-Identifier: MIT
// Hand-made geometry for pipeline tests: a ring of pinhole cameras and standing COCO persons.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/camera.h"
#include "core/joints.h"
#include "core/pipeline/frame_stats.h"
#include "core/pipeline/options.h"
#include "core/pipeline/pipeline_types.h"
#include "core/pipeline/view_geometry.h"
#include "core/poses.h"

namespace rpt::test {

// A camera at `center` looking at `target` (z up), 1000x1000 px, focal 800 px.
Camera LookAtCamera(const Eigen::Vector3d& center, const Eigen::Vector3d& target, const std::string& name);

// `n` cameras on a circle of radius 4 m at height 2.5 m, looking at (0, 0, 1).
std::vector<Camera> RingCameras(int n);

// The 17 COCO joints of a standing person (about 1.75 m) at floor position (x, y), facing +x
// rotated by `yaw` radians. Columns: x, y, z, score (1).
Eigen::Matrix4Xd StandingPerson(double x, double y, double yaw = 0.0);

// Projects 3D persons (4 x J each) into every camera: one Poses2D per camera.
std::vector<Poses2D> ProjectPersons(const std::vector<Camera>& cameras, const std::vector<Eigen::Matrix4Xd>& persons);

// What the steps after undistortion read of COCO-17 `views` of `cameras`: each camera's view
// geometry, the default core joints and the views undistorted with the default options.
void UndistortCocoViews(const std::vector<Camera>& cameras, const std::vector<Poses2D>& views,
                        std::vector<ViewGeometry>* geometry, std::vector<int>* core, PreparedViews* prepared);

// The persons of one frame of COCO-17 `views` of `cameras` (at time 0) through a new Triangulator
// with `options`; its stats in `stats` when given.
Poses3D ProcessOneFrame(const std::vector<Camera>& cameras, const std::vector<Poses2D>& views,
                        const TriangulatorOptions& options, FrameStats* stats = nullptr);

}  // namespace rpt::test
