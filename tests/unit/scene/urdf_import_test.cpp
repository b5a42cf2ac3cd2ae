// collido import urdf: a robot with every joint kind (continuous, revolute, prismatic, fixed, a
// mimic, a mimic of a mimic) and every geometry kind (box, cylinder, sphere, a package:// mesh
// scaled per axis) imported, loaded back, its link poses checked against forward kinematics written
// out here, and its self-collision rule checked against the exact oracle; then URDFs that are
// refused.
#include <collido/urdf/urdf_import.h>

#include <cmath>
#include <filesystem>
#include <set>

#include <gtest/gtest.h>

#include <collido/oracle/exact_oracle.h>
#include <collido/scene/scene.h>

#include "support/test_paths.h"

namespace collido {
namespace {

constexpr const char* kRobot = R"(<robot name="every_kind">
  <link name="base"><collision><geometry><box size="0.4 0.4 0.2"/></geometry></collision>
    <collision><origin xyz="0.19 0.06 0.3"/><geometry><box size="0.04 0.04 0.7"/></geometry>
    </collision></link>
  <link name="column"><collision><origin xyz="0 0 0.25"/>
    <geometry><cylinder radius="0.05" length="0.5"/></geometry></collision></link>
  <link name="arm">
    <collision><origin xyz="0.2 0 0"/><geometry><box size="0.4 0.06 0.06"/></geometry></collision>
    <collision><origin xyz="0.4 0 0"/><geometry><sphere radius="0.05"/></geometry></collision>
  </link>
  <link name="slider"><collision><origin xyz="0.02 0 0"/><geometry>
    <mesh filename="package://parts/meshes/part.obj" scale="0.1 0.05 0.2"/></geometry></collision>
  </link>
  <link name="flange"/>
  <link name="tool"><collision><geometry><sphere radius="0.03"/></geometry></collision></link>
  <joint name="yaw" type="continuous"><parent link="base"/><child link="column"/>
    <origin xyz="0 0 0.1"/><axis xyz="0 0 1"/></joint>
  <joint name="shoulder" type="revolute"><parent link="column"/><child link="arm"/>
    <origin xyz="0 0 0.5" rpy="0 0 0.3"/><axis xyz="0 1 0"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <joint name="extend" type="prismatic"><parent link="arm"/><child link="slider"/>
    <origin xyz="0.4 0 0"/><axis xyz="1 0 0"/><limit lower="0" upper="0.3" effort="1" velocity="1"/>
  </joint>
  <joint name="mount" type="fixed"><parent link="slider"/><child link="flange"/>
    <origin xyz="0.1 0 0" rpy="1.5707963 0 0"/></joint>
  <joint name="wrist" type="revolute"><parent link="flange"/><child link="tool"/>
    <origin xyz="0 0 0.05"/><axis xyz="0 0 1"/><limit lower="-2" upper="2" effort="1" velocity="1"/>
    <mimic joint="shoulder" multiplier="-1" offset="0.1"/></joint>
  <link name="finger"><collision><geometry><sphere radius="0.01"/></geometry></collision></link>
  <joint name="grip" type="revolute"><parent link="tool"/><child link="finger"/>
    <origin xyz="0 0 0.03"/><axis xyz="0 1 0"/><limit lower="-3" upper="3" effort="1" velocity="1"/>
    <mimic joint="wrist" multiplier="2"/></joint>
</robot>
)";

// A unit cube with a corner at the origin.
constexpr const char* kCube =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n"
    "f 1 3 4\nf 1 4 2\nf 5 6 8\nf 5 8 7\nf 1 2 6\nf 1 6 5\nf 3 7 8\nf 3 8 4\nf 1 5 7\nf 1 7 3\n"
    "f 2 4 8\nf 2 8 6\n";

Pose move(double x, double y, double z) {
  return Pose(Eigen::Translation3d(x, y, z));
}
Pose turn(double angle, const Eigen::Vector3d& axis) {
  return Pose(Eigen::AngleAxisd(angle, axis));
}

// Every object's world pose for (yaw, shoulder, extend), written out from the URDF above.
std::map<std::string, Pose> expectedPoses(double yaw, double shoulder, double extend) {
  const Pose column = move(0, 0, 0.1) * turn(yaw, Eigen::Vector3d::UnitZ());
  const Pose arm = column * move(0, 0, 0.5) * turn(0.3, Eigen::Vector3d::UnitZ()) *
                   turn(shoulder, Eigen::Vector3d::UnitY());
  const Pose slider = arm * move(0.4, 0, 0) * move(extend, 0, 0);
  const Pose flange = slider * move(0.1, 0, 0) * turn(1.5707963, Eigen::Vector3d::UnitX());
  const Pose tool = flange * move(0, 0, 0.05) * turn(-shoulder + 0.1, Eigen::Vector3d::UnitZ());
  return {
      {"base", Pose::Identity()},
      {"base_2", move(0.19, 0.06, 0.3)},
      {"column", column * move(0, 0, 0.25)},
      {"arm", arm * move(0.2, 0, 0)},
      {"arm_2", arm * move(0.4, 0, 0)},
      {"slider", slider * move(0.02, 0, 0)},
      {"tool", tool},
      {"finger", tool * move(0, 0, 0.03) * turn(2 * (-shoulder + 0.1), Eigen::Vector3d::UnitY())}};
}

struct Files {
  std::string dir;
  std::string urdf;
  std::string csv;
};

Files writeRobot(const std::string& robot, const std::string& csv) {
  Files f;
  f.dir = test::makeTempDirectory("urdf");
  std::filesystem::create_directories(f.dir + "/parts/urdf");
  std::filesystem::create_directories(f.dir + "/parts/meshes");
  test::writeFile(f.dir + "/parts/meshes/part.obj", kCube);
  test::writeFile(f.dir + "/far_box.obj", kCube);
  f.urdf = f.dir + "/parts/urdf/robot.urdf";
  test::writeFile(f.urdf, robot);
  f.csv = f.dir + "/joints.csv";
  test::writeFile(f.csv, csv);
  return f;
}

// The written robot and trajectory with the far box as environment, into scene/robot.json.
UrdfImportRequest requestWithEnvironment(const Files& f) {
  UrdfImportRequest request;
  request.urdf = f.urdf;
  request.trajectory = f.csv;
  request.environment = {{f.dir + "/far_box.obj"}};
  request.output = f.dir + "/scene/robot.json";
  return request;
}

TEST(UrdfImport, LinksFollowForwardKinematicsAndSelfCollisionFollowsTheRules) {
  // Frame 0 is the reference configuration (every joint at 0), where the post on the base
  // (base_2) touches the arm.
  const Files f = writeRobot(kRobot, "yaw, shoulder,extend\n0,0,0\n0.5,-0.4,0.1\n3.0,0.9,0.3\n");
  UrdfImportRequest request = requestWithEnvironment(f);
  request.disable_pairs = {{"tool", "base"}};
  request.enable_pairs = {{"base", "column"}};
  const Result<UrdfImport> imported = importUrdf(request);
  ASSERT_TRUE(imported.ok()) << imported.status().toString();
  EXPECT_EQ(imported.value().moving_joints, 3u);  // the mimic follows the shoulder
  EXPECT_EQ(imported.value().disabled_pairs, 1u);

  const Result<Scene> loaded = loadScene(request.output);
  ASSERT_TRUE(loaded.ok()) << loaded.status().toString();
  const Scene& scene = loaded.value();
  ASSERT_EQ(scene.frames, 3u);
  EXPECT_EQ(scene.up, Eigen::Vector3d::UnitZ());  // the view keeps URDF's z up
  const double values[3][3] = {{0, 0, 0}, {0.5, -0.4, 0.1}, {3.0, 0.9, 0.3}};
  std::map<std::string, std::size_t> index;
  for (std::size_t i = 0; i < scene.objects.size(); ++i)
    index[scene.objects[i].name] = i;
  for (std::size_t frame = 0; frame < 3; ++frame) {
    for (const auto& [name, pose] :
         expectedPoses(values[frame][0], values[frame][1], values[frame][2])) {
      ASSERT_EQ(index.count(name), 1u) << name;
      const Pose& got = scene.objects[index[name]].poseAt(frame);
      EXPECT_LT((got.matrix() - pose.matrix()).cwiseAbs().maxCoeff(), 1e-12)
          << name << " in frame " << frame;
    }
  }
  // Mounted on their parents: the arm on the column, its second element on its first, the tool
  // on the slider (the flange has no geometry), the environment on its own.
  EXPECT_EQ(scene.objects[index["arm"]].parent, index["column"]);
  EXPECT_EQ(scene.objects[index["arm_2"]].parent, index["arm"]);
  EXPECT_EQ(scene.objects[index["tool"]].parent, index["slider"]);
  EXPECT_FALSE(scene.objects[index["env_far_box"]].parent.has_value());
  // The slider's mesh, a unit cube scaled per axis.
  EXPECT_DOUBLE_EQ(scene.objects[index["slider"]].mesh->vertices.row(2).maxCoeff(), 0.2);

  // Self-collision: one group query over the robot asking each object pair of two links, unless
  // adjacent (but the enabled base and column), disabled (tool and base) or in contact in frame
  // 0, the reference; the rest are its `except` pairs, and so are a link's own elements.
  const std::map<std::string, std::string> link_of = {
      {"base", "base"}, {"base_2", "base"},   {"column", "column"}, {"arm", "arm"},
      {"arm_2", "arm"}, {"slider", "slider"}, {"tool", "tool"},     {"finger", "finger"}};
  const std::set<std::set<std::string>> adjacent = {{"base", "column"},
                                                    {"column", "arm"},
                                                    {"arm", "slider"},
                                                    {"slider", "tool"},
                                                    {"tool", "finger"}};
  const SceneQuery& self = scene.queries.front();
  ASSERT_EQ(self.name, "self-collision");
  EXPECT_EQ(self.request.kind, QueryKind::kAllPairs);
  EXPECT_FALSE(self.asksPair(index["base"], index["base_2"]));
  std::set<std::pair<std::string, std::string>> asked;
  for (const auto& [a, link_a] : link_of) {
    for (const auto& [b, link_b] : link_of) {
      if (self.asksPair(index[a], index[b])) asked.insert({a, b});
    }
  }
  std::size_t touching_links = 0;
  std::set<std::set<std::string>> touching;
  for (const auto& [a, link_a] : link_of) {
    for (const auto& [b, link_b] : link_of) {
      if (link_a >= link_b) continue;
      const SceneObject& oa = scene.objects[index[a]];
      const SceneObject& ob = scene.objects[index[b]];
      if (exactIntersectingPairs(*oa.mesh, oa.poseAt(0), *ob.mesh, ob.poseAt(0),
                                 OracleMode::kFirstPair)
              .intersecting)
        touching.insert({link_a, link_b});
    }
  }
  for (const auto& [a, link_a] : link_of) {
    for (const auto& [b, link_b] : link_of) {
      if (link_a == link_b) continue;
      const std::set<std::string> links = {link_a, link_b};
      const bool expected = links == std::set<std::string>{"base", "column"} ||
                            (adjacent.count(links) == 0 && touching.count(links) == 0 &&
                             links != std::set<std::string>{"base", "tool"});
      const bool got = asked.count({a, b}) != 0;
      EXPECT_EQ(got, expected) << a << " - " << b;
    }
  }
  EXPECT_EQ(imported.value().self_pairs, asked.size() / 2);  // both orders are in `asked`
  for (const auto& links : touching)
    touching_links += adjacent.count(links) == 0 ? 1 : 0;
  EXPECT_EQ(imported.value().touching_pairs, touching_links);
  EXPECT_GT(touching_links, 0u) << "the test robot has no touching pair to leave out";

  // The robot against its environment, and the tool's clearance.
  EXPECT_EQ(queryKindName(scene.queries[scene.queries.size() - 2].request.kind),
            std::string("all_pairs"));
  EXPECT_EQ(scene.queries.back().name, "clearance: finger-env_far_box");
}

TEST(UrdfImport, ClearanceIsAskedForTheNamedLinks) {
  const Files f = writeRobot(kRobot, "yaw\n0\n0.5\n");
  UrdfImportRequest request = requestWithEnvironment(f);
  request.clearance_links = {"tool", "slider"};
  ASSERT_TRUE(importUrdf(request).ok());
  const Result<Scene> loaded = loadScene(request.output);
  ASSERT_TRUE(loaded.ok()) << loaded.status().toString();
  std::vector<std::string> clearances;
  for (const SceneQuery& query : loaded.value().queries) {
    if (query.name.rfind("clearance: ", 0) == 0) clearances.push_back(query.name);
  }
  EXPECT_EQ(clearances, (std::vector<std::string>{"clearance: tool-env_far_box",
                                                  "clearance: slider-env_far_box"}));

  // A link that is not there, or has no geometry, is refused by name.
  for (const auto& [link, problem] :
       {std::pair<std::string, std::string>{"elbow", "no link of robot"},
        std::pair<std::string, std::string>{"flange", "link has no collision geometry"}}) {
    request.clearance_links = {link};
    const Result<UrdfImport> refused = importUrdf(request);
    ASSERT_FALSE(refused.ok()) << link;
    EXPECT_NE(refused.status().message().find("--clearance " + link + ": " + problem),
              std::string::npos)
        << refused.status().message();
  }
}

// --first-contact asks each named link's first contact with each environment object over every
// step; the same refusals as --clearance, naming the option.
TEST(UrdfImport, FirstContactIsAskedForTheNamedLinks) {
  const Files f = writeRobot(kRobot, "yaw\n0\n0.5\n");
  UrdfImportRequest request = requestWithEnvironment(f);
  request.first_contact_links = {"tool"};
  ASSERT_TRUE(importUrdf(request).ok());
  const Result<Scene> loaded = loadScene(request.output);
  ASSERT_TRUE(loaded.ok()) << loaded.status().toString();
  const SceneQuery& last = loaded.value().queries.back();
  EXPECT_EQ(last.name, "first contact: tool-env_far_box");
  EXPECT_EQ(queryKindName(last.request.kind), std::string("first_contact"));

  request.first_contact_only = true;
  ASSERT_TRUE(importUrdf(request).ok());
  const Result<Scene> edges = loadScene(request.output);
  ASSERT_TRUE(edges.ok()) << edges.status().toString();
  ASSERT_EQ(edges.value().queries.size(), 1u);
  EXPECT_EQ(edges.value().queries[0].name, "first contact: tool-env_far_box");
  request.first_contact_links.clear();
  const Result<UrdfImport> nothing = importUrdf(request);
  ASSERT_FALSE(nothing.ok());
  EXPECT_NE(nothing.status().message().find("--first-contact-only: no --first-contact link"),
            std::string::npos);
  request.first_contact_only = false;

  request.first_contact_links = {"elbow"};
  const Result<UrdfImport> refused = importUrdf(request);
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.status().message().find("--first-contact elbow: no link of robot"),
            std::string::npos)
      << refused.status().message();
}

// An environment mesh placed by --environment FILE@X,Y,Z,ROLL,PITCH,YAW sits there in every
// frame, loaded back: URDF's rpy, about the fixed axes.
TEST(UrdfImport, EnvironmentMeshesArePlacedWhereTheArgumentSays) {
  const Files f = writeRobot(kRobot, "yaw\n0\n0.5\n");
  UrdfImportRequest request = requestWithEnvironment(f);
  const Result<EnvironmentMesh> placed =
      parseEnvironmentMesh(f.dir + "/far_box.obj@1.5,-2,0.25,0.1,-0.2,0.3");
  ASSERT_TRUE(placed.ok()) << placed.status().toString();
  EXPECT_EQ(placed.value().file, f.dir + "/far_box.obj");
  request.environment = {placed.value(), {f.dir + "/far_box.obj"}};
  ASSERT_TRUE(importUrdf(request).ok());
  const Result<Scene> loaded = loadScene(request.output);
  ASSERT_TRUE(loaded.ok()) << loaded.status().toString();
  std::map<std::string, const SceneObject*> by_name;
  for (const SceneObject& object : loaded.value().objects)
    by_name[object.name] = &object;
  ASSERT_EQ(by_name.count("env_far_box"), 1u);
  ASSERT_EQ(by_name.count("env_far_box_2"), 1u);
  // Written out: roll about x, then pitch about y, then yaw about z, all about the fixed axes.
  const double cr = std::cos(0.1), sr = std::sin(0.1), cp = std::cos(-0.2), sp = std::sin(-0.2),
               cy = std::cos(0.3), sy = std::sin(0.3);
  Eigen::Matrix3d roll, pitch, yaw;
  roll << 1, 0, 0, 0, cr, -sr, 0, sr, cr;
  pitch << cp, 0, sp, 0, 1, 0, -sp, 0, cp;
  yaw << cy, -sy, 0, sy, cy, 0, 0, 0, 1;
  for (std::size_t frame = 0; frame < 2; ++frame) {
    const Pose& got = by_name["env_far_box"]->poseAt(frame);
    EXPECT_LT((got.linear() - yaw * pitch * roll).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LT((got.translation() - Eigen::Vector3d(1.5, -2, 0.25)).cwiseAbs().maxCoeff(), 1e-12);
    // The second stays at its file's coordinates, whatever the first's pose.
    EXPECT_TRUE(by_name["env_far_box_2"]->poseAt(frame).isApprox(Pose::Identity(), 1e-12));
  }
}

TEST(UrdfImport, EnvironmentArgumentsAreReadOrRefusedByName) {
  const Result<EnvironmentMesh> moved = parseEnvironmentMesh("bench.stl@0.5,0,-0.4");
  ASSERT_TRUE(moved.ok()) << moved.status().toString();
  EXPECT_EQ(moved.value().file, "bench.stl");
  EXPECT_TRUE(moved.value().pose.linear().isIdentity());
  EXPECT_EQ(moved.value().pose.translation(), Eigen::Vector3d(0.5, 0, -0.4));
  // An '@' followed by something other than numbers is part of the name.
  for (const char* name : {"bench.stl", "parts@v2/bench.stl", "bench@2x.stl"}) {
    const Result<EnvironmentMesh> plain = parseEnvironmentMesh(name);
    ASSERT_TRUE(plain.ok()) << name;
    EXPECT_EQ(plain.value().file, name);
    EXPECT_TRUE(plain.value().pose.isApprox(Pose::Identity()));
  }
  for (const auto& [argument, problem] : std::vector<std::pair<std::string, std::string>>{
           {"bench.stl@1,2", "got 2 numbers"},
           {"bench.stl@1,2,3,4", "got 4 numbers"},
           {"bench.stl@1,nan,3", "Y is not a finite number"},
           {"bench.stl@1,2,3,0,0,inf", "YAW is not a finite number"},
           {"bench.stl@1e999,0,0", "X is not a finite number"},
           {"@1,2,3", "no mesh file before the '@'"}}) {
    const Result<EnvironmentMesh> refused = parseEnvironmentMesh(argument);
    ASSERT_FALSE(refused.ok()) << argument;
    const std::string& message = refused.status().message();
    EXPECT_EQ(message.rfind("--environment '" + argument + "': ", 0), 0u) << message;
    EXPECT_NE(message.find(problem), std::string::npos) << message;
  }
}

TEST(UrdfImport, BadRobotsAreRefusedNamingTheLinkJointOrColumn) {
  const auto refused = [](const std::string& robot, const std::string& csv,
                          const std::vector<std::string>& words) {
    const Files f = writeRobot(robot, csv);
    UrdfImportRequest request;
    request.urdf = f.urdf;
    request.trajectory = f.csv;
    request.output = f.dir + "/robot.json";
    const Result<UrdfImport> imported = importUrdf(request);
    ASSERT_FALSE(imported.ok());
    for (const std::string& word : words)
      EXPECT_NE(imported.status().message().find(word), std::string::npos)
          << imported.status().message();
    EXPECT_FALSE(std::filesystem::exists(request.output));
  };
  const std::string robot = kRobot;
  const auto replaced = [&](const std::string& from, const std::string& to) {
    std::string text = robot;
    text.replace(text.find(from), from.size(), to);
    return text;
  };
  const std::string csv = "yaw\n0\n";
  refused(replaced("meshes/part.obj", "meshes/missing.obj"), csv,
          {"robot.urdf", "link 'slider'", "package://parts/meshes/missing.obj", "not found"});
  refused(replaced("type=\"prismatic\"", "type=\"spherical\""), csv,
          {"robot.urdf", "extend", "spherical"});
  refused(replaced("</robot>",
                   "<joint name=\"loop\" type=\"fixed\"><parent link=\"tool\"/>"
                   "<child link=\"base\"/></joint></robot>"),
          csv, {"robot.urdf", "'loop'", "make a cycle of links"});
  refused(robot, "yaw,elbow\n0,0\n", {"joints.csv", "column 'elbow' names no moving joint"});
  refused(robot, "yaw,yaw\n0,0\n", {"joints.csv", "joint 'yaw' has two columns"});
  refused(replaced("scale=\"0.1 0.05 0.2\"", "scale=\"-0.1 0.05 0.2\""), csv,
          {"robot.urdf", "link 'slider'", "not > 0"});
  refused(replaced("</robot>",
                   "<joint name=\"again\" type=\"fixed\"><parent link=\"base\"/>"
                   "<child link=\"tool\"/></joint></robot>"),
          csv, {"robot.urdf", "link 'tool' is the child of joints"});
  refused(robot, "shoulder\n1.5\n", {"joints.csv", "line 2, column 'shoulder'", "beyond"});
}

}  // namespace
}  // namespace collido
