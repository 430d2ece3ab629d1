// SPDX-License-Identifier: MIT
#include "tests/pipeline/test_scene.h"

#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "core/pipeline/triangulator.h"
#include "core/pipeline/undistort.h"

namespace rpt::test {

Camera LookAtCamera(const Eigen::Vector3d& center, const Eigen::Vector3d& target, const std::string& name) {
  const Eigen::Vector3d z = (target - center).normalized();
  const Eigen::Vector3d x = z.cross(Eigen::Vector3d::UnitZ()).normalized();
  const Eigen::Vector3d y = z.cross(x);
  Eigen::Matrix3d R;
  R.row(0) = x;
  R.row(1) = y;
  R.row(2) = z;
  Camera camera = Camera::FromCenter(R, center);
  camera.name = name;
  camera.width = 1000;
  camera.height = 1000;
  camera.K << 800, 0, 500, 0, 800, 500, 0, 0, 1;
  return camera;
}

std::vector<Camera> RingCameras(int n) {
  std::vector<Camera> cameras;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * i / n + 0.3;
    cameras.push_back(LookAtCamera(Eigen::Vector3d(4 * std::cos(a), 4 * std::sin(a), 2.5), Eigen::Vector3d(0, 0, 1),
                                   "cam" + std::to_string(i)));
  }
  return cameras;
}

Eigen::Matrix4Xd StandingPerson(double x, double y, double yaw) {
  // Local frame: x forward, y left, z up. Order = CocoBodyJoints().
  const double local[17][3] = {
      {0.10, 0.00, 1.62},   // nose
      {0.08, 0.03, 1.66},   {0.08, -0.03, 1.66},   // eyes
      {0.02, 0.07, 1.64},   {0.02, -0.07, 1.64},   // ears
      {0.00, 0.19, 1.45},   {0.00, -0.19, 1.45},   // shoulders
      {0.02, 0.24, 1.17},   {0.02, -0.24, 1.17},   // elbows
      {0.08, 0.25, 0.93},   {0.08, -0.25, 0.93},   // wrists
      {0.00, 0.11, 0.93},   {0.00, -0.11, 0.93},   // hips
      {0.03, 0.12, 0.50},   {0.03, -0.12, 0.50},   // knees
      {-0.02, 0.12, 0.08},  {-0.02, -0.12, 0.08},  // ankles
  };
  const Eigen::Matrix3d R = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  Eigen::Matrix4Xd person(4, 17);
  for (int j = 0; j < 17; ++j) {
    person.col(j).head<3>() = R * Eigen::Vector3d(local[j][0], local[j][1], local[j][2]) + Eigen::Vector3d(x, y, 0);
    person(3, j) = 1.0;
  }
  return person;
}

std::vector<Poses2D> ProjectPersons(const std::vector<Camera>& cameras, const std::vector<Eigen::Matrix4Xd>& persons) {
  std::vector<Poses2D> views(cameras.size());
  for (size_t v = 0; v < cameras.size(); ++v) {
    views[v].Clear(persons.empty() ? 17 : static_cast<int>(persons[0].cols()));
    for (const Eigen::Matrix4Xd& person : persons) {
      auto pose = views[v].AddPerson();
      for (int j = 0; j < person.cols(); ++j) {
        Eigen::Vector2d uv;
        if (person(3, j) > 0 && cameras[v].Project(person.col(j).head<3>(), &uv)) {
          pose.col(j) << uv.x(), uv.y(), 1.0;
        }
      }
    }
  }
  return views;
}

void UndistortCocoViews(const std::vector<Camera>& cameras, const std::vector<Poses2D>& views,
                        std::vector<ViewGeometry>* geometry, std::vector<int>* core, PreparedViews* prepared) {
  geometry->clear();
  for (const Camera& c : cameras) geometry->push_back(MakeViewGeometry(c));
  core->clear();
  for (const auto& name : DefaultCoreJoints()) core->push_back(FindJoint(CocoBodyJoints(), name));
  steps::Undistort(UndistortOptions{},
                   {.views = views,
                    .cameras = cameras,
                    .geometry = *geometry,
                    .derived = {},
                    .core_joints = *core,
                    .num_output_joints = 17},
                   prepared);
}

Poses3D ProcessOneFrame(const std::vector<Camera>& cameras, const std::vector<Poses2D>& views,
                        const TriangulatorOptions& options, FrameStats* stats) {
  Triangulator tri(cameras, CocoBodyJoints(), options);
  Poses3D persons;
  FrameStats local;
  tri.Process(views, 0.0, &persons, stats != nullptr ? stats : &local);
  return persons;
}

}  // namespace rpt::test
