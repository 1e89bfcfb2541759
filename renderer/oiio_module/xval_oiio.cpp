// The module xval_oiio: OpenImageIO's decoders for the image formats xval
// does not read itself (image/other_formats.h). Built as a shared module
// next to the xval executable and opened with dlopen on the first such
// file, so a process that reads only EXRs and PNGs never loads
// OpenImageIO's libraries.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/oiioversion.h>

#include <memory>
#include <stdexcept>

#include "image/oiio_module_api.h"

namespace xval {
namespace {

namespace OIIO = OIIO_NAMESPACE;

const char* version() { return OIIO_VERSION_STRING; }

ImageHeader header(const std::filesystem::path& file) {
  auto in = OIIO::ImageInput::open(file.string());
  if (!in) throw std::runtime_error(file.string() + ": cannot open image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  return {spec.width, spec.height, spec.depth, spec.nchannels};
}

// The file name OpenImageIO chooses an embedded image's reader by: from
// its first bytes (JPEG's FF D8 FF); PNGs never come here (png_file.h).
std::string embeddedImageName(const std::vector<std::uint8_t>& b) {
  return b.size() >= 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF ? "embedded.jpg" : "embedded.png";
}

OtherFormatImage decode(const std::filesystem::path& file, const std::vector<std::uint8_t>* embedded,
                        const std::string& what, const OtherFormatCheck& check) {
  // Stored values: OpenImageIO multiplies colour by alpha on reading unless
  // told that the caller wants the file's unassociated values.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  std::unique_ptr<OIIO::Filesystem::IOMemReader> memory;
  if (embedded) {
    memory = std::make_unique<OIIO::Filesystem::IOMemReader>(embedded->data(), embedded->size());
    // The readers take the proxy from the configuration.
    void* proxy = memory.get();
    config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
  }
  auto in = embedded ? OIIO::ImageInput::open(embeddedImageName(*embedded), &config, memory.get())
                     : OIIO::ImageInput::open(file.string(), &config);
  if (!in) throw std::runtime_error(what + ": cannot open image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (check) check({spec.width, spec.height, spec.depth, spec.nchannels});
  OtherFormatImage o;
  o.width = spec.width, o.height = spec.height, o.channels = spec.nchannels;
  o.format = in->format_name();
  for (int c = 0; c < spec.nchannels; ++c) o.names.push_back(spec.channelnames[size_t(c)]);
  o.unassociated = spec.get_int_attribute("oiio:UnassociatedAlpha", 0) != 0;
  const size_t n = size_t(spec.width) * size_t(spec.height) * size_t(spec.nchannels);
  bool ok;
  if (spec.format == OIIO::TypeDesc::UINT8) {
    o.bits = 8, o.u8.resize(n);
    ok = in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, o.u8.data());
  } else if (spec.format == OIIO::TypeDesc::UINT16) {
    o.bits = 16, o.u16.resize(n);
    ok = in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT16, o.u16.data());
  } else {
    o.bits = 32, o.f32.resize(n);
    ok = in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, o.f32.data());
  }
  if (!ok) throw std::runtime_error(what + ": cannot decode " + o.format + " image: " + in->geterror());
  return o;
}

const OiioModuleApi kApi = {kOiioModuleAbi, version, header, decode};

}  // namespace
}  // namespace xval

extern "C" __attribute__((visibility("default"))) const xval::OiioModuleApi* xval_oiio_module() {
  return &xval::kApi;
}
