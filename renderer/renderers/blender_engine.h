// The Blender harness's renderers (renderers/blender.cpp): Cycles
// (`blender`) and EEVEE (`eevee`) are one factory, blenderEngineRenderer,
// given what differs between them; blender_native.cpp uses the harness's
// script check and Cycles' refusal.
#pragma once

#include <string>

#include "blender/blender_render.h"
#include "renderers/renderer.h"

namespace xval::renderers {

// What differs between the Cycles and EEVEE renderers.
struct BlenderEngineFacts {
  BlenderEngine engine = BlenderEngine::Cycles;
  std::string id, display_name, summary;
  double cpu_share = 1.0;     // Renderer::cpu_share, measured per engine
  PrecisionModel precision;   // Renderer::precision (docs/precision-models.md)
};

// A renderer running the harness with that engine: the glTF export, the
// node-tree rebuild of the model, batches in one Blender process.
Renderer blenderEngineRenderer(const BlenderEngineFacts& facts);

// A native tier (renderers/blender_native.cpp): Blender's own BSDFs
// (blender/native_bsdf.h) rendered by that engine, for the scenes that name
// it (every_scene false).
Renderer nativeBsdfRenderer(BlenderEngine engine, const std::string& id, const std::string& display_name,
                            const std::string& summary);

// Why the harness cannot run on this machine ("" when it can): its script.
std::string blenderScriptMissing();
// The Cycles harness's refusal of a scene, "" when it can render it.
std::string blenderRefusal(const Scene& scene);

}  // namespace xval::renderers
