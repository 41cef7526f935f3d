// Prescribed motion of kinematic bodies: constant velocities against the closed form (a point
// turned by exactly 90 degrees), keyframes (linear position, shortest-arc slerp, holding before
// and after, looping), the velocity against a finite difference of the pose, and the scene
// file's "motion" object: a valid document and every error under its exact JSON path.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "coupling/mesh/mesh_transform.h"
#include "coupling/motion/prescribed_motion.h"
#include "coupling/motion/prescribed_motion_json.h"

namespace upf {
namespace {

constexpr double kPi = std::numbers::pi;

RigidPose pose_at(const Eigen::Vector3d& position, const Eigen::Vector3d& axis, double degrees) {
  return {position, rotation_from_axis_angle_degrees(axis, degrees)};
}

// The angle in radians of the rotation taking a to b.
double angle_between(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  return a.angularDistance(b);
}

void expect_near(const Eigen::Vector3d& actual, const Eigen::Vector3d& expected, double tolerance) {
  EXPECT_LE((actual - expected).norm(), tolerance)
      << "got " << actual.transpose() << ", expected " << expected.transpose();
}

// Central difference of where the body point placed at p is, against point_velocity().
void expect_velocity_is_derivative(const PrescribedMotion& motion, const Eigen::Vector3d& pivot,
                                   const Eigen::Vector3d& p, double t) {
  const double h = 1e-5;
  const Eigen::Vector3d difference =
      (apply(motion.pose(t + h), pivot, p) - apply(motion.pose(t - h), pivot, p)) / (2 * h);
  const RigidPose pose = motion.pose(t);
  const Eigen::Vector3d v = point_velocity(motion.velocity(t), pose, pivot, apply(pose, pivot, p));
  expect_near(v, difference, 1e-9);
}

// A three-segment motion with general axes; the third key turns 350 degrees about z from the
// second, which the shortest arc makes -10 degrees.
PrescribedMotion three_segments(double loop = 0) {
  const Eigen::Vector3d axis(1, 2, 3);
  return PrescribedMotion::keyframes({{0.5, pose_at({0, 0, 0}, axis, 0)},
                                      {1.5, pose_at({0.2, -0.1, 0.3}, axis, 60)},
                                      {2.0, pose_at({0.2, 0.4, 0.3}, {0, 0, 1}, 20)},
                                      {3.0, pose_at({0.0, 0.4, 0.3}, {0, 0, 1}, 370)}},
                                     loop);
}

TEST(PrescribedMotion, ConstantTurnsAPointByNinetyDegrees) {
  const Eigen::Vector3d linear(0.1, -0.2, 0.3), angular(0, 0, 2.5);
  const PrescribedMotion motion = PrescribedMotion::constant(linear, angular);
  const Eigen::Vector3d pivot(1, 1, 0.5), p(2, 1, 0.5);  // 1 m from the pivot along x
  const double t = (kPi / 2) / angular.norm();
  const RigidPose pose = motion.pose(t);
  expect_near(pose.position, linear * t, 1e-15);
  // About +z: the offset (1, 0, 0) turns to (0, 1, 0); the pivot travels with the body.
  expect_near(apply(pose, pivot, p), pivot + linear * t + Eigen::Vector3d(0, 1, 0), 1e-12);
  // There the point moves at v + w x (0, 1, 0) = v + (-2.5, 0, 0).
  expect_near(point_velocity(motion.velocity(t), pose, pivot, apply(pose, pivot, p)),
              linear + Eigen::Vector3d(-2.5, 0, 0), 1e-12);
  EXPECT_TRUE(motion.moves());
}

TEST(PrescribedMotion, ConstantStartsAtTheIdentityAndTurnsAboutAGeneralAxis) {
  const Eigen::Vector3d angular(0.3, -0.4, 1.2);
  const PrescribedMotion motion = PrescribedMotion::constant({1, 0, 0}, angular);
  EXPECT_EQ(motion.pose(0).position, Eigen::Vector3d::Zero());
  EXPECT_TRUE(motion.pose(0).orientation.isApprox(Eigen::Quaterniond::Identity(), 0));
  const double t = 0.7;
  EXPECT_NEAR(angle_between(motion.pose(t).orientation, Eigen::Quaterniond::Identity()),
              angular.norm() * t, 1e-12);
  // The axis is fixed: it is not moved by the rotation.
  expect_near(motion.pose(t).orientation * angular, angular, 1e-12);
  const RigidVelocity v = motion.velocity(t);
  EXPECT_EQ(v.linear, Eigen::Vector3d(1, 0, 0));
  EXPECT_EQ(v.angular, angular);
  for (double s : {0.0, 0.3, 2.0})
    expect_velocity_is_derivative(motion, {0.5, 0, -1}, {1, 2, 3}, s);
}

TEST(PrescribedMotion, AtRestDoesNotMove) {
  const PrescribedMotion motion = PrescribedMotion::at_rest();
  EXPECT_FALSE(motion.moves());
  EXPECT_EQ(motion.pose(5).position, Eigen::Vector3d::Zero());
  EXPECT_EQ(motion.velocity(5).angular, Eigen::Vector3d::Zero());
  // One key, or keys that all agree: a fixed displacement, no motion.
  EXPECT_FALSE(PrescribedMotion::keyframes({{0, pose_at({1, 0, 0}, {0, 0, 1}, 30)}}).moves());
  EXPECT_FALSE(PrescribedMotion::keyframes(
                   {{0, pose_at({1, 0, 0}, {0, 0, 1}, 30)}, {1, pose_at({1, 0, 0}, {0, 0, 1}, 30)}})
                   .moves());
  EXPECT_TRUE(three_segments().moves());
}

TEST(PrescribedMotion, KeyframeMidpointInterpolatesPositionAndSlerpsTheAngle) {
  const PrescribedMotion motion =
      PrescribedMotion::keyframes({{0, RigidPose{}}, {2, pose_at({2, 0, -4}, {0, 0, 1}, 90)}});
  const RigidPose mid = motion.pose(1);
  expect_near(mid.position, {1, 0, -2}, 1e-15);
  EXPECT_NEAR(angle_between(mid.orientation, Eigen::Quaterniond::Identity()), kPi / 4, 1e-12);
  EXPECT_TRUE(mid.orientation.isApprox(rotation_from_axis_angle_degrees({0, 0, 1}, 45), 1e-14));
  // A quarter of the way, a quarter of the angle.
  EXPECT_NEAR(angle_between(motion.pose(0.5).orientation, Eigen::Quaterniond::Identity()), kPi / 8,
              1e-12);
  const RigidVelocity v = motion.velocity(1);
  expect_near(v.linear, {1, 0, -2}, 1e-15);
  expect_near(v.angular, {0, 0, kPi / 4}, 1e-14);
}

TEST(PrescribedMotion, SlerpTakesTheShortestArc) {
  const PrescribedMotion motion = three_segments();
  // From 20 to 370 degrees about z is -10 degrees the short way, at -10 degrees per second.
  const RigidPose from = motion.pose(2.0);
  const RigidPose mid = motion.pose(2.5);
  EXPECT_NEAR(angle_between(from.orientation, mid.orientation), 5 * kPi / 180, 1e-12);
  expect_near(motion.velocity(2.5).angular, {0, 0, -10 * kPi / 180}, 1e-12);
}

TEST(PrescribedMotion, VelocityIsTheDerivativeOfThePoseInsideEverySegment) {
  const PrescribedMotion motion = three_segments();
  const Eigen::Vector3d pivot(0.3, -0.2, 0.1);
  for (const Eigen::Vector3d& p : {Eigen::Vector3d(1, 0.5, -0.5), Eigen::Vector3d(-0.4, 0, 2)})
    for (double t : {0.6, 1.0, 1.45, 1.6, 1.9, 2.2, 2.9})
      expect_velocity_is_derivative(motion, pivot, p, t);
}

TEST(PrescribedMotion, KeysAreReachedAndVelocityIsThatOfTheSegmentStartingThere) {
  const PrescribedMotion motion = three_segments();
  const RigidPose key = pose_at({0.2, -0.1, 0.3}, {1, 2, 3}, 60);
  expect_near(motion.pose(1.5).position, key.position, 1e-15);
  EXPECT_NEAR(angle_between(motion.pose(1.5).orientation, key.orientation), 0, 1e-7);
  // At 1.5 the segment 1.5 -> 2.0 starts: it moves in y only.
  expect_near(motion.velocity(1.5).linear, {0, 1, 0}, 1e-12);
  expect_near(motion.velocity(std::nextafter(1.5, 0.0)).linear, {0.2, -0.1, 0.3}, 1e-12);
}

TEST(PrescribedMotion, HoldsTheFirstPoseBeforeAndTheLastPoseAfter) {
  const PrescribedMotion motion = three_segments();
  for (double t : {-1.0, 0.0, 0.49}) {
    EXPECT_EQ(motion.pose(t).position, Eigen::Vector3d::Zero()) << t;
    EXPECT_NEAR(angle_between(motion.pose(t).orientation, Eigen::Quaterniond::Identity()), 0,
                1e-15);
    EXPECT_EQ(motion.velocity(t).linear, Eigen::Vector3d::Zero()) << t;
    EXPECT_EQ(motion.velocity(t).angular, Eigen::Vector3d::Zero()) << t;
  }
  const RigidPose last = pose_at({0.0, 0.4, 0.3}, {0, 0, 1}, 370);
  for (double t : {3.0, 3.5, 100.0}) {
    expect_near(motion.pose(t).position, last.position, 0);
    EXPECT_NEAR(angle_between(motion.pose(t).orientation, last.orientation), 0, 1e-7);
    EXPECT_EQ(motion.velocity(t).linear, Eigen::Vector3d::Zero()) << t;
    EXPECT_EQ(motion.velocity(t).angular, Eigen::Vector3d::Zero()) << t;
  }
}

TEST(PrescribedMotion, LoopRepeatsWithItsPeriod) {
  const PrescribedMotion motion = three_segments(4.0);
  const PrescribedMotion once = three_segments();
  for (double t : {0.2, 0.7, 1.5, 2.6, 3.5}) {
    for (int period : {1, 2, 5}) {
      const double later = t + 4.0 * period;
      expect_near(motion.pose(later).position, once.pose(t).position, 1e-12);
      EXPECT_NEAR(angle_between(motion.pose(later).orientation, once.pose(t).orientation), 0, 1e-7);
      expect_near(motion.velocity(later).linear, once.velocity(t).linear, 1e-12);
      expect_near(motion.velocity(later).angular, once.velocity(t).angular, 1e-12);
    }
  }
  // From the last key (3.0) to the end of the period (4.0) it holds still, then starts over.
  EXPECT_EQ(motion.velocity(3.9).linear, Eigen::Vector3d::Zero());
  EXPECT_EQ(motion.pose(4.0).position, Eigen::Vector3d::Zero());
  // A period equal to the last key's time is allowed.
  expect_near(three_segments(3.0).pose(3.0 + 1.0).position, once.pose(1.0).position, 1e-12);
}

TEST(PrescribedMotion, BadKeyframesAreRefused) {
  using Keys = std::vector<std::pair<double, RigidPose>>;
  EXPECT_THROW(PrescribedMotion::keyframes(Keys{}), std::invalid_argument);
  EXPECT_THROW(PrescribedMotion::keyframes(Keys{{1, {}}, {1, {}}}), std::invalid_argument);
  EXPECT_THROW(PrescribedMotion::keyframes(Keys{{-1, {}}}), std::invalid_argument);
  EXPECT_THROW(PrescribedMotion::keyframes(Keys{{0, {}}, {2, {}}}, 1.5), std::invalid_argument);
  EXPECT_THROW(PrescribedMotion::constant({std::nan(""), 0, 0}, {0, 0, 0}), std::invalid_argument);
}

// --- The scene file's "motion" object ---

const std::string kPath = "/bodies/0/motion";

std::string all_problems(const std::vector<InputProblem>& problems) {
  std::string all;
  for (const auto& p : problems) all += p.where + ": " + p.message + "\n";
  return all;
}

// Reading `node` fails with exactly one problem, at `where`, whose message contains `what`.
void expect_problem(const nlohmann::json& node, const std::string& where, const std::string& what) {
  std::vector<InputProblem> problems;
  JsonInput input(problems);
  EXPECT_FALSE(read_prescribed_motion(node, kPath, input)) << node.dump();
  ASSERT_EQ(problems.size(), 1u) << all_problems(problems);
  EXPECT_EQ(problems[0].where, where) << all_problems(problems);
  EXPECT_NE(problems[0].message.find(what), std::string::npos) << all_problems(problems);
}

TEST(PrescribedMotionJson, ReadsConstantVelocitiesAndPivot) {
  const auto node = nlohmann::json::parse(R"({
    "linear_velocity": [0.5, 0, 0], "angular_velocity": [0, 0, 3.14], "pivot": [1, 2, 3]})");
  std::vector<InputProblem> problems;
  JsonInput input(problems);
  const auto motion = read_prescribed_motion(node, kPath, input);
  const auto pivot = read_pivot(node, kPath, input);
  ASSERT_TRUE(motion) << all_problems(problems);
  EXPECT_TRUE(problems.empty()) << all_problems(problems);
  EXPECT_EQ(motion->velocity(0).linear, Eigen::Vector3d(0.5, 0, 0));
  EXPECT_EQ(motion->velocity(0).angular, Eigen::Vector3d(0, 0, 3.14));
  ASSERT_TRUE(pivot);
  EXPECT_EQ(*pivot, Eigen::Vector3d(1, 2, 3));
}

TEST(PrescribedMotionJson, DefaultsAreRest) {
  std::vector<InputProblem> problems;
  JsonInput input(problems);
  const auto node = nlohmann::json::object();
  const auto motion = read_prescribed_motion(node, kPath, input);
  ASSERT_TRUE(motion);
  EXPECT_FALSE(motion->moves());
  EXPECT_FALSE(read_pivot(node, kPath, input));
  EXPECT_TRUE(problems.empty()) << all_problems(problems);
}

TEST(PrescribedMotionJson, ReadsKeyframesWithLoop) {
  const auto node = nlohmann::json::parse(R"({
    "keyframes": [
      {"time": 0, "position": [0, 0, 0], "rotation": {"axis": [0, 0, 1], "degrees": 0}},
      {"time": 1, "position": [0.2, 0, 0]},
      {"time": 2, "rotation": {"axis": [0, 0, 2], "degrees": 90}}],
    "loop": 2.5})");
  std::vector<InputProblem> problems;
  JsonInput input(problems);
  const auto motion = read_prescribed_motion(node, kPath, input);
  ASSERT_TRUE(motion) << all_problems(problems);
  EXPECT_TRUE(problems.empty()) << all_problems(problems);
  EXPECT_FALSE(read_pivot(node, kPath, input));
  expect_near(motion->pose(0.5).position, {0.1, 0, 0}, 1e-15);
  expect_near(motion->pose(1.5).position, {0.1, 0, 0}, 1e-15);  // no position: back to zero
  EXPECT_NEAR(angle_between(motion->pose(1.5).orientation, Eigen::Quaterniond::Identity()), kPi / 4,
              1e-12);
  expect_near(motion->velocity(1.5).angular, {0, 0, kPi / 2}, 1e-12);
  expect_near(motion->pose(3.0).position, {0.1, 0, 0}, 1e-12);  // 3.0 is 0.5 into the 2nd loop
}

TEST(PrescribedMotionJson, VelocitiesAndKeyframesTogether) {
  expect_problem(nlohmann::json::parse(R"({"angular_velocity": [0, 0, 1],
                                           "keyframes": [{"time": 0}]})"),
                 kPath, "either velocities (linear_velocity, angular_velocity) or keyframes");
}

TEST(PrescribedMotionJson, EmptyKeyframes) {
  expect_problem(nlohmann::json::parse(R"({"keyframes": []})"), kPath + "/keyframes",
                 "at least one keyframe is required");
  expect_problem(nlohmann::json::parse(R"({"keyframes": {"time": 0}})"), kPath + "/keyframes",
                 "expected an array of keyframes, found an object");
}

TEST(PrescribedMotionJson, NonIncreasingTimesNameBothKeyframes) {
  expect_problem(nlohmann::json::parse(R"({"keyframes": [{"time": 1}, {"time": 0.5}]})"),
                 kPath + "/keyframes/1/time",
                 "keyframe times must increase strictly: keyframe 1 at 0.5 s follows keyframe 0 "
                 "at 1 s");
  expect_problem(nlohmann::json::parse(R"({"keyframes": [{"time": 0}, {"time": 2}, {"time": 2}]})"),
                 kPath + "/keyframes/2/time", "keyframe 2 at 2 s follows keyframe 1 at 2 s");
}

TEST(PrescribedMotionJson, NegativeOrMissingTime) {
  expect_problem(nlohmann::json::parse(R"({"keyframes": [{"time": -0.5}]})"),
                 kPath + "/keyframes/0/time", "value -0.5 is out of range [0, 1e+07] s");
  expect_problem(nlohmann::json::parse(R"({"keyframes": [{"time": 0}, {"position": [1, 0, 0]}]})"),
                 kPath + "/keyframes/1/time", "missing");
}

TEST(PrescribedMotionJson, LoopShorterThanTheKeysOrNotPositive) {
  expect_problem(nlohmann::json::parse(R"({"keyframes": [{"time": 0}, {"time": 2}], "loop": 1.5})"),
                 kPath + "/loop",
                 "the loop period 1.5 s is shorter than the last keyframe's time 2 s");
  expect_problem(nlohmann::json::parse(R"({"keyframes": [{"time": 0}], "loop": 0})"),
                 kPath + "/loop", "value 0 is out of range (0, 1e+07] s");
  expect_problem(nlohmann::json::parse(R"({"linear_velocity": [1, 0, 0], "loop": 2})"),
                 kPath + "/loop", "a loop period needs keyframes");
}

TEST(PrescribedMotionJson, NonFiniteNumbers) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  auto velocity = nlohmann::json::parse(R"({"linear_velocity": [0, 0, 0]})");
  velocity["linear_velocity"][1] = inf;
  expect_problem(velocity, kPath + "/linear_velocity/1", "expected a finite number");
  auto time = nlohmann::json::parse(R"({"keyframes": [{"time": 0}]})");
  time["keyframes"][0]["time"] = nan;
  expect_problem(time, kPath + "/keyframes/0/time", "out of range");
  auto position = nlohmann::json::parse(R"({"keyframes": [{"time": 0, "position": [0, 0, 0]}]})");
  position["keyframes"][0]["position"][2] = nan;
  expect_problem(position, kPath + "/keyframes/0/position/2", "expected a finite number");
  auto degrees = nlohmann::json::parse(
      R"({"keyframes": [{"time": 0, "rotation": {"axis": [0, 0, 1], "degrees": 0}}]})");
  degrees["keyframes"][0]["rotation"]["degrees"] = inf;
  expect_problem(degrees, kPath + "/keyframes/0/rotation/degrees", "out of range");
}

TEST(PrescribedMotionJson, ZeroRotationAxis) {
  expect_problem(nlohmann::json::parse(R"({"keyframes": [{"time": 0},
                   {"time": 1, "rotation": {"axis": [0, 0, 0], "degrees": 30}}]})"),
                 kPath + "/keyframes/1/rotation/axis", "the rotation axis must not be zero");
}

TEST(PrescribedMotionJson, UnknownKeysSuggestTheirNames) {
  expect_problem(nlohmann::json::parse(R"({"angular_velocty": [0, 0, 1]})"),
                 kPath + "/angular_velocty", "did you mean 'angular_velocity'?");
  expect_problem(nlohmann::json::parse(R"({"keyframes": [{"time": 0, "positon": [0, 0, 1]}]})"),
                 kPath + "/keyframes/0/positon", "did you mean 'position'?");
}

TEST(PrescribedMotionJson, EveryBadKeyframeIsReportedAtOnce) {
  const auto node = nlohmann::json::parse(R"({"keyframes": [
      {"time": 1}, {"time": 0.5}, {"time": -1}, 3,
      {"time": 2, "rotation": {"axis": [0, 0, 0], "degrees": 1}}], "loop": 1.5})");
  std::vector<InputProblem> problems;
  JsonInput input(problems);
  EXPECT_FALSE(read_prescribed_motion(node, kPath, input));
  const std::string all = all_problems(problems);
  EXPECT_EQ(problems.size(), 5u) << all;
  for (const std::string where : {"/keyframes/1/time", "/keyframes/2/time", "/keyframes/3",
                                  "/keyframes/4/rotation/axis", "/loop"})
    EXPECT_NE(all.find(kPath + where + ": "), std::string::npos) << where << "\n" << all;
}

TEST(PrescribedMotionJson, BadPivot) {
  const auto node = nlohmann::json::parse(R"({"pivot": [0, 1]})");
  std::vector<InputProblem> problems;
  JsonInput input(problems);
  EXPECT_TRUE(read_prescribed_motion(node, kPath, input));
  EXPECT_FALSE(read_pivot(node, kPath, input));
  ASSERT_EQ(problems.size(), 1u) << all_problems(problems);
  EXPECT_EQ(problems[0].where, kPath + "/pivot");
}

}  // namespace
}  // namespace upf
