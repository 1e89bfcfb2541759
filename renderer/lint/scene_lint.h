// Warnings for a loaded scene that every renderer draws alike but that
// cannot be what its author meant: pure checks over the scene, never an
// error and never a verdict (`xval validate` prints them, records them in
// results.json and shows them in the report; docs/scene-format.md,
// "Warnings"). Each rule below is sufficient, not necessary: it warns
// only where the stated fact holds, and may miss scenes as odd.
//
// Subjects are named as the scene file's fields are: "lights[0]",
// "objects[1]" (with the primitive for a model file of several), "camera".
//
// The rules (codes as in SceneWarning::code):
//
//   light_inside_closed_mesh: a point or spot light strictly inside the
//     solid one object mesh bounds. The mesh, its vertices of equal
//     position made one (the built-in shapes repeat them along their uv
//     seams and at a sphere's poles), passes whyNotAnOutwardSolid
//     (geometry/closed_surface.h: closed, consistently oriented, embedded,
//     outward) and its winding number around the light's position rounds
//     to an integer n >= 1 and lies within 0.25 of it (a point on the
//     surface has a half-integer one: not "strictly" inside). Then every
//     ray from the light leaves the solid through the surface along its
//     outward normal: wherever the light first reaches the surface it
//     reaches its back (N.L < 0), and whatever of it faces the light lies
//     behind a wall of it. Lights cast no shadows here, so renderers agree
//     on an image no physical light would make: an object lit from inside
//     its own walls (none, for a convex one) and the rest lit through it.
//
//   camera_inside_closed_mesh: the camera's position strictly inside such
//     a solid (the same test): every pixel sees that object's inside (its
//     back faces) or what is enclosed with the camera; nothing else.
//
//   gouraud_spot_between_vertices: shading "gouraud", a spot light whose
//     axis ray (from its position along its direction) hits a triangle of
//     an object mesh at a point per-pixel shading would light (the
//     interpolated vertex normal there faces the light, N.L > 0), and no
//     triangle of that mesh has all three vertices inside the cone (angle
//     to the axis <= cutoff_deg). Gouraud shades the vertices and blends
//     their colours over each triangle, so the spot's full contribution
//     appears only inside a triangle whose three vertices are all lit;
//     with none, the lit disc the cone cuts out of the surface is drawn as
//     ramps between lit and unlit vertices (as nothing at all when no
//     vertex is inside: a two-triangle plane with the cone in its middle)
//     and neither its brightness nor its edge appears anywhere.
//
//   light_adds_nothing: a light whose colour is (0, 0, 0): it adds nothing
//     to any point of any image (every model multiplies by the colour).
#pragma once

#include <string>
#include <vector>

#include "geometry/mesh.h"
#include "scene/scene.h"

namespace xval {

struct SceneWarning {
  std::string code;     // one of the rules above
  std::string subject;  // "lights[0]", "objects[1]", "camera"
  std::string message;  // what holds and what it means, in a sentence
};

// "SUBJECT: MESSAGE [CODE]": how a warning is printed.
std::string describe(const SceneWarning& w);

// "warning: SCENE_NAME: " and describe(w): how a command prints it.
std::string warningLine(const Scene& scene, const SceneWarning& w);
// lintScene's warnings, one warningLine each, after "PREFIX: " on stderr
// (PREFIX: "xval render", ...); returns them.
std::vector<SceneWarning> printSceneWarnings(const char* prefix, const Scene& scene);

// Every rule over every light, object (each of its meshes: geometry/
// scene_meshes.h) and the camera, in that order of rules and then of
// lights and objects.
std::vector<SceneWarning> lintScene(const Scene& scene);

// The rules' geometric tests, for one mesh (exposed for the unit tests).
// The winding number of `mesh` around x: the triangles' signed solid
// angles over 4 pi (+1 inside an outward solid, 0 outside).
double windingNumber(const TriangleMesh& mesh, glm::dvec3 x);
// x strictly inside the outward solid `mesh` bounds (the first rule).
bool strictlyInsideClosedMesh(const TriangleMesh& mesh, glm::dvec3 x);
// The third rule's condition for one spot light and one mesh.
bool spotConeFallsBetweenVertices(const SpotLight& spot, const TriangleMesh& mesh);

}  // namespace xval
