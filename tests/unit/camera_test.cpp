// Camera rays through pixel centres (camera/camera.h's convention).
#include <gtest/gtest.h>

#include "camera/camera.h"

using namespace xval;

TEST(Camera, CentreOfAnOddImageLooksAtTheTarget) {
  Camera c;
  c.position = {1, 2, 3};
  c.target = {1, 2, -7};
  c.width = 5, c.height = 3;
  CameraRays r(c);
  glm::dvec3 d = r.direction(2 + 0.5, 1 + 0.5);  // pixel (2, 1)'s centre
  EXPECT_LT(glm::length(d - glm::dvec3(0, 0, -1)), 1e-15);
}

TEST(Camera, PixelCentresAndOrientation) {
  Camera c;  // at (0,0,4.2) looking down -z, +y up
  c.width = 4, c.height = 2;
  c.fov_y_deg = 90.0;  // tan(fov/2) = 1
  CameraRays r(c);
  // Pixel (0, 0) is top-left: sx = (2 * 0.5 / 4 - 1) * 1 * 2 = -1.5,
  // sy = (1 - 2 * 0.5 / 2) * 1 = 0.5.
  glm::dvec3 d = r.direction(0.5, 0.5);
  glm::dvec3 expect = glm::normalize(glm::dvec3(-1.5, 0.5, -1.0));
  EXPECT_LT(glm::length(d - expect), 1e-15);
  // Row 0 is the top: +y; column 0 is the left: -x (right-handed, +y up).
  EXPECT_GT(d.y, 0);
  EXPECT_LT(d.x, 0);
  // Symmetry: pixel (3, 1) mirrors pixel (0, 0).
  glm::dvec3 m = r.direction(3.5, 1.5);
  EXPECT_NEAR(m.x, -d.x, 1e-15);
  EXPECT_NEAR(m.y, -d.y, 1e-15);
}

TEST(Camera, UpVectorIsOrthogonalised) {
  Camera c;
  c.position = {0, 0, 0};
  c.target = {0, 0, -1};
  c.up = {0, 1, 1};  // not orthogonal to the view direction
  CameraRays r(c);
  EXPECT_NEAR(glm::dot(r.up, r.forward), 0.0, 1e-15);
  EXPECT_LT(glm::length(r.up - glm::dvec3(0, 1, 0)), 1e-15);
  EXPECT_LT(glm::length(r.right - glm::dvec3(1, 0, 0)), 1e-15);
}
