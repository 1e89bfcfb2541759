// Expecting a scene text to be refused with a message that names the file.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <initializer_list>
#include <string>

#include "scene/json_reader.h"
#include "scene_file/scene_loader.h"

namespace xval::test {

// parseScene(text, file) must throw a SceneError whose message holds the
// file's path and every one of `needles`.
inline void expectSceneError(const std::filesystem::path& file, const std::string& text,
                             std::initializer_list<std::string> needles) {
  try {
    parseScene(text, file);
    ADD_FAILURE() << "no error for: " << text;
  } catch (const SceneError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(file.string()), std::string::npos) << msg;
    for (const auto& n : needles) EXPECT_NE(msg.find(n), std::string::npos) << "'" << n << "' not in: " << msg;
  }
}

}  // namespace xval::test
