#include "blender/multilayer_exr.h"

#include <stdexcept>

#include "common/export_common.h"
#include "image/exr_file.h"
#include "image/image.h"
#include "image/image_header.h"

namespace xval {

MultilayerChannels readMultilayerChannels(const std::filesystem::path& file, int width, int height,
                                          const std::vector<std::string>& suffixes) {
  requireRegularImageFile(file);
  try {
    ExrInput in(file);
    const ImageHeader header = in.header();
    // The header must claim the camera's size before any pixel is allocated.
    const std::string problem = imageHeaderProblem(header, readImageLimits(width, height));
    if (!problem.empty()) throw ExternalToolError(file.string() + ": the image " + problem);
    MultilayerChannels out;
    out.width = header.width;
    out.height = header.height;
    out.nchannels = int(suffixes.size());
    std::vector<std::string> names;
    for (const std::string& suffix : suffixes) {
      const std::string* found = nullptr;
      for (const std::string& n : in.channels())
        if (!found && n.size() >= suffix.size() && n.compare(n.size() - suffix.size(), suffix.size(), suffix) == 0)
          found = &n;
      if (!found) throw ExternalToolError(file.string() + ": no channel *" + suffix);
      out.index.push_back(int(names.size()));
      names.push_back(*found);
    }
    out.pixels.resize(size_t(out.width) * size_t(out.height) * names.size());
    std::vector<ExrTarget> targets;
    for (size_t k = 0; k < names.size(); ++k)
      targets.push_back({names[k], out.pixels.data() + k, names.size(), size_t(out.width) * names.size()});
    in.read(targets);
    return out;
  } catch (const ExternalToolError&) {
    throw;
  } catch (const std::runtime_error& e) {
    // ExrInput's errors name the file.
    throw ExternalToolError(e.what());
  }
}

}  // namespace xval
