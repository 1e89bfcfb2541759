#include "blender/native_lambert.h"

#include <numbers>
#include <stdexcept>

namespace xval {

namespace {
}

void checkNativeLambertScene(const Scene& s) {
  auto* l = std::get_if<Lambert>(&s.material.model);
  if (!l || l->c0 != glm::dvec3(1.0) || s.material.texture || s.material.base_color != glm::dvec3(1.0))
    throw std::runtime_error(s.name + ": the native-Lambert check needs an untextured white "
                             "lambert material (c0 = base_color = [1,1,1])");
  if (hasObjectMaterials(s))
    throw std::runtime_error(s.name + ": the native-Lambert check needs the scene's one material on every object");
  if (s.lights.size() != 1 || !std::holds_alternative<PointLight>(s.lights[0]))
    throw std::runtime_error(s.name + ": the native-Lambert check needs exactly one point light");
  const auto& p = std::get<PointLight>(s.lights[0]);
  if (p.color.x != p.color.y || p.color.y != p.color.z)
    throw std::runtime_error(s.name + ": the native-Lambert light must be white (I, I, I)");
  if (p.attenuation.linear != 0.0 || p.attenuation.quadratic != 1.0 || p.attenuation.constant > 1e-6)
    throw std::runtime_error(s.name + ": the native-Lambert light needs attenuation "
                             "{constant ~ 0 (<= 1e-6), linear 0, quadratic 1}: the inverse square");
  if (s.shading != ShadingMode::Phong)
    throw std::runtime_error(s.name + ": the native-Lambert check uses smooth (phong) shading");
}

void scaleNativeLambert(const Scene& s, Image& img) {
  checkNativeLambertScene(s);
  // P = I watts (RAW import): DiffDir = I / (4 pi^2) max(N.L,0) / d^2.
  const float k = float(4.0 * std::numbers::pi * std::numbers::pi);
  for (size_t i = 0; i < img.rgba.size(); i += 4)
    for (int c = 0; c < 3; ++c) img.rgba[i + c] = std::min(1.0f, std::max(0.0f, img.rgba[i + c] * k));
}

}  // namespace xval
