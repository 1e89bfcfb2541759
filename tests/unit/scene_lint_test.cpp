// Scene warnings (lint/scene_lint.h): each rule warns on the scene it
// describes and stays silent on its near neighbours.
#include <gtest/gtest.h>

#include "lint/scene_lint.h"

using namespace xval;

namespace {

// The codes of lintScene's warnings, in order.
std::vector<std::string> codes(const Scene& s) {
  std::vector<std::string> out;
  for (const SceneWarning& w : lintScene(s)) out.push_back(w.code + " " + w.subject);
  return out;
}
using Codes = std::vector<std::string>;

Scene sphereScene() {
  Scene s;
  s.objects = {UvSphere{}};  // radius 1 at the origin; the camera at (0, 0, 4.2)
  return s;
}

// An axis-aligned cube [-1, 1]^3, outward, 12 triangles; without the +z
// face (`open`) it has a hole.
TriangleMesh cube(bool open = false) {
  TriangleMesh m;
  for (int k = 0; k < 8; ++k) {
    m.positions.push_back({k & 1 ? 1.0 : -1.0, k & 2 ? 1.0 : -1.0, k & 4 ? 1.0 : -1.0});
    m.normals.push_back(glm::normalize(m.positions.back()));
  }
  m.triangles = {{0, 2, 3}, {0, 3, 1}, {0, 1, 5}, {0, 5, 4}, {0, 4, 6}, {0, 6, 2},
                 {1, 3, 7}, {1, 7, 5}, {2, 6, 7}, {2, 7, 3}};
  if (!open) m.triangles.insert(m.triangles.end(), {{4, 5, 7}, {4, 7, 6}});
  return m;
}

// An n x n grid of quads over [-1, 1]^2 at z = 0, facing +z.
TriangleMesh grid(int n) {
  TriangleMesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      m.positions.push_back({-1.0 + 2.0 * i / n, -1.0 + 2.0 * j / n, 0.0});
      m.normals.push_back({0, 0, 1});
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
      m.triangles.push_back({a, b, c});
      m.triangles.push_back({a, c, d});
    }
  return m;
}

SpotLight spotDown(glm::dvec3 at, double cutoff_deg) {
  SpotLight l;
  l.position = at, l.direction = {0, 0, -1}, l.cutoff_deg = cutoff_deg;
  return l;
}

}  // namespace

TEST(SceneLint, WindingNumberOfACube) {
  EXPECT_NEAR(windingNumber(cube(), {0.2, -0.3, 0.5}), 1.0, 1e-12);
  EXPECT_NEAR(windingNumber(cube(), {3.0, 0.0, 0.0}), 0.0, 1e-12);
  EXPECT_NEAR(windingNumber(cube(), {0.0, 0.0, 1.0}), 0.5, 1e-12);  // on a face
  EXPECT_TRUE(strictlyInsideClosedMesh(cube(), {0.2, -0.3, 0.5}));
  EXPECT_FALSE(strictlyInsideClosedMesh(cube(), {0.0, 0.0, 1.0}));  // on the surface: not strictly
  EXPECT_FALSE(strictlyInsideClosedMesh(cube(), {0.0, 0.0, 1.5}));
  // A cube with a hole: the light escapes through it, whatever the winding says.
  EXPECT_GT(windingNumber(cube(true), {0.0, 0.0, -0.5}), 0.75);
  EXPECT_FALSE(strictlyInsideClosedMesh(cube(true), {0.0, 0.0, -0.5}));
}

TEST(SceneLint, PointOrSpotLightInsideASphere) {
  Scene s = sphereScene();
  s.lights = {PointLight{{0.1, 0.2, 0.3}}, spotDown({0, 0.5, 0}, 30.0), PointLight{{0, 0, 2}}, DirectionalLight{}};
  EXPECT_EQ(codes(s), (Codes{"light_inside_closed_mesh lights[0]", "light_inside_closed_mesh lights[1]"}));
  // The sphere's seams and poles repeat vertices by position: welded, it
  // is closed. Moved away, scaled down or opened (a plane), nothing.
  s.lights = {PointLight{{0, 0, 2}}, spotDown({0, 0, 1.5}, 30.0)};
  EXPECT_EQ(codes(s), Codes{});
  s.lights = {PointLight{{0.1, 0.2, 0.3}}};
  s.objects[0].transform.scale = glm::dvec3(0.2);
  EXPECT_EQ(codes(s), Codes{});
  s.objects = {Plane{}};
  EXPECT_EQ(codes(s), Codes{});
}

TEST(SceneLint, LightInsideATransformedKnotTube) {
  Scene s;
  TorusKnot k;
  k.segments_along = 192, k.segments_around = 12;
  s.objects = {SceneObject(k)};
  s.objects[0].transform.translate = {5, 0, 0};
  // The centre line at t = 0 is (R + r, 0, 0): inside the tube.
  s.lights = {PointLight{{5.0 + k.major_radius + k.minor_radius, 0, 0}}, PointLight{{5, 0, 0}}};
  EXPECT_EQ(codes(s), Codes{"light_inside_closed_mesh lights[0]"});
}

TEST(SceneLint, CameraInsideASphere) {
  Scene s = sphereScene();
  s.lights = {DirectionalLight{}};
  EXPECT_EQ(codes(s), Codes{});
  s.camera.position = {0, 0, 0.5};
  EXPECT_EQ(codes(s), Codes{"camera_inside_closed_mesh camera"});
}

// The case: a two-triangle plane, Gouraud, a spot cone in its
// middle that holds none of its corners.
TEST(SceneLint, GouraudSpotBetweenTheVerticesOfAPlane) {
  Scene s;
  s.objects = {Plane{}};  // 2 x 2 at the origin, facing +z
  s.lights = {spotDown({0, 0, 1}, 20.0)};
  s.shading = ShadingMode::Gouraud;
  EXPECT_EQ(codes(s), Codes{"gouraud_spot_between_vertices lights[0]"});
  // Phong and flat shade per pixel (flat: per triangle, but at the hit).
  s.shading = ShadingMode::Phong;
  EXPECT_EQ(codes(s), Codes{});
  s.shading = ShadingMode::Gouraud;
  // A cone wide enough to hold the corners: every vertex lit, no warning.
  s.lights = {spotDown({0, 0, 1}, 60.0)};
  EXPECT_EQ(codes(s), Codes{});
  // The axis misses the plane, or meets it from behind (N.L < 0: unlit
  // per pixel too).
  s.lights = {spotDown({3, 0, 1}, 20.0)};
  EXPECT_EQ(codes(s), Codes{});
  s.lights = {spotDown({0, 0, 1}, 20.0)};
  s.objects = {Plane{{0, 0, 0}, {0, 0, -1}}};
  EXPECT_EQ(codes(s), Codes{});
}

TEST(SceneLint, GouraudSpotAgainstTheMeshSpacing) {
  const SpotLight spot = spotDown({0.01, 0.02, 1}, 20.0);  // a disc of radius 0.36 on z = 0
  EXPECT_TRUE(spotConeFallsBetweenVertices(spot, grid(1)));   // no vertex inside
  EXPECT_TRUE(spotConeFallsBetweenVertices(spot, grid(2)));   // one vertex (the centre), no triangle
  EXPECT_FALSE(spotConeFallsBetweenVertices(spot, grid(8)));  // spacing 0.25: whole triangles inside
  EXPECT_FALSE(spotConeFallsBetweenVertices(spot, grid(64)));
  // A coarse sphere warns, the default one does not.
  Scene s = sphereScene();
  s.shading = ShadingMode::Gouraud;
  s.lights = {spotDown({0.01, 0.02, 3}, 5.0)};
  EXPECT_EQ(codes(s), Codes{});
  UvSphere coarse;
  coarse.segments_longitude = 6, coarse.segments_latitude = 4;
  s.objects = {coarse};
  EXPECT_EQ(codes(s), Codes{"gouraud_spot_between_vertices lights[0]"});
}

TEST(SceneLint, BlackLightAddsNothing) {
  Scene s = sphereScene();
  s.lights = {DirectionalLight{{0, -1, 0}, glm::dvec3(0.0)}, AmbientLight{glm::dvec3(0.0, 0.0, 0.01)},
              AmbientLight{glm::dvec3(0.0)}};
  EXPECT_EQ(codes(s), (Codes{"light_adds_nothing lights[0]", "light_adds_nothing lights[2]"}));
}

TEST(SceneLint, DescribeNamesSubjectMessageAndCode) {
  EXPECT_EQ(describe({"light_adds_nothing", "lights[2]", "the point light's colour is (0, 0, 0): it adds nothing"}),
            "lights[2]: the point light's colour is (0, 0, 0): it adds nothing [light_adds_nothing]");
}
