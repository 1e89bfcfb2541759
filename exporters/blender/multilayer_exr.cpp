#include "blender/multilayer_exr.h"

#include <OpenImageIO/imageio.h>

#include "common/export_common.h"
#include "image/image.h"
#include "image/image_header.h"

namespace xval {

namespace OIIO = OIIO_NAMESPACE;

MultilayerChannels readMultilayerChannels(const std::filesystem::path& file, int width, int height,
                                          const std::vector<std::string>& suffixes) {
  requireRegularImageFile(file);
  auto in = OIIO::ImageInput::open(file.string());
  if (!in) throw ExternalToolError(file.string() + ": cannot open: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  // The header must claim the camera's size before any pixel is allocated.
  const std::string problem =
      imageHeaderProblem({spec.width, spec.height, spec.depth, spec.nchannels}, readImageLimits(width, height));
  if (!problem.empty()) throw ExternalToolError(file.string() + ": the image " + problem);
  MultilayerChannels out;
  out.width = spec.width;
  out.height = spec.height;
  out.nchannels = spec.nchannels;
  for (const std::string& suffix : suffixes) {
    int found = -1;
    for (int i = 0; i < spec.nchannels && found < 0; ++i) {
      const std::string& n = spec.channelnames[i];
      if (n.size() >= suffix.size() && n.compare(n.size() - suffix.size(), suffix.size(), suffix) == 0) found = i;
    }
    if (found < 0) throw ExternalToolError(file.string() + ": no channel *" + suffix);
    out.index.push_back(found);
  }
  out.pixels.resize(size_t(spec.width) * size_t(spec.height) * size_t(spec.nchannels));
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, out.pixels.data()))
    throw ExternalToolError(file.string() + ": cannot read: " + in->geterror());
  return out;
}

}  // namespace xval
