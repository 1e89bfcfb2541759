#include "image/exr_file.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfTestFile.h>
#include <OpenEXR/ImfThreading.h>
#include <OpenEXR/OpenEXRConfig.h>
#include <Imath/half.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

namespace xval {

namespace {

// OpenEXR compresses and decompresses a file's chunks on its global thread
// pool, side by side; it starts with none. One thread per core, as
// OpenImageIO set it up before (its "exr_threads" default).
void startExrThreads() {
  static std::once_flag once;
  std::call_once(once, [] { Imf::setGlobalThreadCount(int(std::max(1u, std::thread::hardware_concurrency()))); });
}

Imf::Compression compressionNamed(const std::string& file, const char* name) {
  static const std::pair<const char*, Imf::Compression> kNames[] = {
      {"none", Imf::NO_COMPRESSION},    {"rle", Imf::RLE_COMPRESSION},     {"zips", Imf::ZIPS_COMPRESSION},
      {"zip", Imf::ZIP_COMPRESSION},    {"piz", Imf::PIZ_COMPRESSION},     {"pxr24", Imf::PXR24_COMPRESSION},
      {"b44", Imf::B44_COMPRESSION},    {"b44a", Imf::B44A_COMPRESSION},   {"dwaa", Imf::DWAA_COMPRESSION},
      {"dwab", Imf::DWAB_COMPRESSION}};
  for (const auto& [n, c] : kNames)
    if (std::strcmp(n, name) == 0) return c;
  throw std::runtime_error(file + ": unknown EXR compression \"" + name + "\"");
}

}  // namespace

void writeExrFile(const std::filesystem::path& file, int width, int height, const std::vector<ExrChannel>& channels,
                  const char* compression, const std::vector<std::pair<std::string, std::string>>& attributes) {
  const std::string name = file.string();
  startExrThreads();
  Imf::Header header(width, height);
  header.compression() = compressionNamed(name, compression);
  for (const auto& [key, value] : attributes) header.insert(key, Imf::StringAttribute(value));
  Imf::FrameBuffer frame;
  // OpenEXR writes a channel only from memory of its own type: half
  // channels are rounded here (Imath's half(float): to nearest, ties to
  // even).
  std::vector<std::vector<Imath::half>> halves;
  for (const ExrChannel& c : channels) {
    header.channels().insert(c.name, Imf::Channel(c.half ? Imf::HALF : Imf::FLOAT));
    if (c.half) {
      std::vector<Imath::half>& h = halves.emplace_back(size_t(width) * size_t(height));
      for (size_t y = 0; y < size_t(height); ++y)
        for (size_t x = 0; x < size_t(width); ++x)
          h[y * size_t(width) + x] = Imath::half(c.base[y * c.row_stride + x * c.pixel_stride]);
      frame.insert(c.name, Imf::Slice(Imf::HALF, reinterpret_cast<char*>(h.data()), sizeof(Imath::half),
                                      size_t(width) * sizeof(Imath::half)));
    } else {
      frame.insert(c.name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(const_cast<float*>(c.base)),
                                      c.pixel_stride * sizeof(float), c.row_stride * sizeof(float)));
    }
  }
  try {
    Imf::OutputFile out(name.c_str(), header);
    out.setFrameBuffer(frame);
    out.writePixels(height);
  } catch (const std::exception& e) {
    throw std::runtime_error(name + ": cannot write EXR: " + e.what());
  }
}

struct ExrInput::File {
  Imf::InputFile in;
  explicit File(const char* name) : in(name) {}
};

ExrInput::ExrInput(const std::filesystem::path& file) : file_(file) {
  startExrThreads();
  try {
    in_ = std::make_unique<File>(file.c_str());
  } catch (const std::exception& e) {
    throw std::runtime_error(file.string() + ": cannot open EXR: " + e.what());
  }
  for (auto c = in_->in.header().channels().begin(); c != in_->in.header().channels().end(); ++c)
    names_.emplace_back(c.name());
}

ExrInput::~ExrInput() = default;

ImageHeader ExrInput::header() const {
  const Imath::Box2i& w = in_->in.header().dataWindow();
  // As 64-bit: a hostile header's window may span more than an int.
  const long long width = (long long)w.max.x - w.min.x + 1, height = (long long)w.max.y - w.min.y + 1;
  auto clamp = [](long long v) { return int(std::clamp<long long>(v, -1, 1LL << 30)); };
  return {clamp(width), clamp(height), 1, int(names_.size())};
}

bool ExrInput::has(const std::string& name) const { return std::find(names_.begin(), names_.end(), name) != names_.end(); }

void ExrInput::read(const std::vector<ExrTarget>& targets) {
  const Imath::Box2i& w = in_->in.header().dataWindow();
  Imf::FrameBuffer frame;
  for (const ExrTarget& t : targets) {
    if (!has(t.name)) throw std::runtime_error(file_.string() + ": EXR has no channel \"" + t.name + "\"");
    // OpenEXR addresses pixels by absolute coordinates: (min.x, min.y) of
    // the data window must land on base. (Not Slice::Make: it takes a row
    // stride of 0, which requireDecodable uses to reuse one row, for "a
    // whole row".) In integers: the offset may point outside the buffer.
    const size_t xs = t.pixel_stride * sizeof(float), ys = t.row_stride * sizeof(float);
    const std::intptr_t origin = std::intptr_t(t.base) - std::intptr_t(w.min.x) * std::intptr_t(xs) -
                                 std::intptr_t(w.min.y) * std::intptr_t(ys);
    frame.insert(t.name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(origin), xs, ys));
  }
  try {
    in_->in.setFrameBuffer(frame);
    in_->in.readPixels(w.min.y, w.max.y);
  } catch (const std::exception& e) {
    throw std::runtime_error(file_.string() + ": cannot read EXR: " + e.what());
  }
}

bool isExrSignature(const unsigned char* bytes, size_t size) {
  return size >= 4 && bytes[0] == 0x76 && bytes[1] == 0x2f && bytes[2] == 0x31 && bytes[3] == 0x01;
}

const char* openexrVersion() { return OPENEXR_VERSION_STRING; }

}  // namespace xval
