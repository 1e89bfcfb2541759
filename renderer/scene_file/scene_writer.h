// Scene -> JSON in the scene-file format (docs/scene-format.md), the
// inverse of scene_loader.h: parseScene(sceneToJson(s)) gives s back.
// Every field is written, defaults included, so the text is complete.
#pragma once

#include <nlohmann/json.hpp>

#include "scene/scene.h"

namespace xval {

// Texture paths are written as given (absolute after loading); pass
// `texture_path` to write another one instead (e.g. an exported copy).
nlohmann::ordered_json sceneToJson(const Scene& s, const std::string* texture_path = nullptr);

}  // namespace xval
