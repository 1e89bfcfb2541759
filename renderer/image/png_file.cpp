#include "image/png_file.h"

#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <algorithm>
#include <cerrno>
#include <cstring>
#include <memory>
#include <stdexcept>

#include "image/image.h"

namespace xval {

namespace {

// libpng reports errors by longjmp to the setjmp of the function that
// called it: every call into libpng below is made from a function whose
// frame holds nothing with a destructor after its setjmp, so the jump
// skips no destructor. The message is kept here and thrown as an
// exception once out of that function.
struct PngState {
  png_structp png = nullptr;
  png_infop info = nullptr;
  std::string message;
  // Where the encoded bytes come from (reading) or go (writing).
  std::FILE* file = nullptr;
  const std::uint8_t* data = nullptr;
  size_t size = 0, pos = 0;
  std::string* out = nullptr;
};

void onError(png_structp png, png_const_charp message) {
  static_cast<PngState*>(png_get_error_ptr(png))->message = message ? message : "libpng error";
  png_longjmp(png, 1);
}
void onWarning(png_structp, png_const_charp) {}

void readBytes(png_structp png, png_bytep to, size_t n) {
  PngState& s = *static_cast<PngState*>(png_get_io_ptr(png));
  if (s.file) {
    if (std::fread(to, 1, n, s.file) != n) png_error(png, "the file ends early or cannot be read");
    return;
  }
  if (n > s.size - s.pos) png_error(png, "the data end early");
  std::memcpy(to, s.data + s.pos, n);
  s.pos += n;
}

void writeBytes(png_structp png, png_bytep from, size_t n) {
  static_cast<PngState*>(png_get_io_ptr(png))->out->append(reinterpret_cast<const char*>(from), n);
}
void flushBytes(png_structp) {}

class PngReader {
 public:
  PngReader(const std::string& what) : what_(what) {
    s_.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &s_, onError, onWarning);
    if (s_.png) s_.info = png_create_info_struct(s_.png);
    if (!s_.png || !s_.info) throw std::runtime_error(what_ + ": cannot start libpng");
    png_set_read_fn(s_.png, &s_, readBytes);
  }
  ~PngReader() {
    png_destroy_read_struct(&s_.png, s_.info ? &s_.info : nullptr, nullptr);
    if (s_.file) std::fclose(s_.file);
  }
  PngState& state() { return s_; }

  // The header, after the expansions.
  ImageHeader readHeader(int& bits) {
    int channels = 0;
    png_uint_32 w = 0, h = 0;
    if (!readInfo(w, h, bits, channels)) fail();
    // As 64-bit before int: a hostile header may claim up to 2^31 - 1.
    auto side = [](png_uint_32 v) { return int(std::min<png_uint_32>(v, 1u << 30)); };
    return {side(w), side(h), 1, channels};
  }
  void readRows(png_bytep* rows) {
    if (!readImage(rows)) fail();
  }

 private:
  bool readInfo(png_uint_32& w, png_uint_32& h, int& bits, int& channels) {
    if (setjmp(png_jmpbuf(s_.png))) return false;
    png_read_info(s_.png, s_.info);
    png_set_expand(s_.png);
    if (png_get_bit_depth(s_.png, s_.info) == 16) png_set_swap(s_.png);  // PNG is big-endian
    png_read_update_info(s_.png, s_.info);
    w = png_get_image_width(s_.png, s_.info);
    h = png_get_image_height(s_.png, s_.info);
    bits = png_get_bit_depth(s_.png, s_.info);
    channels = png_get_channels(s_.png, s_.info);
    return true;
  }
  bool readImage(png_bytep* rows) {
    if (setjmp(png_jmpbuf(s_.png))) return false;
    png_read_image(s_.png, rows);
    png_read_end(s_.png, nullptr);
    return true;
  }
  [[noreturn]] void fail() { throw std::runtime_error(what_ + ": cannot read PNG: " + s_.message); }

  std::string what_;
  PngState s_;
};

PngPixels decodeWith(PngReader& reader, const PngHeaderCheck& check) {
  PngPixels p;
  const ImageHeader h = reader.readHeader(p.bits);
  if (check) check(h);
  p.width = h.width, p.height = h.height, p.channels = h.channels;
  const size_t row = size_t(p.width) * size_t(p.channels);
  std::vector<png_bytep> rows(size_t(p.height));
  if (p.bits == 16) {
    p.words.resize(row * size_t(p.height));
    for (size_t y = 0; y < rows.size(); ++y) rows[y] = reinterpret_cast<png_bytep>(p.words.data() + y * row);
  } else {
    p.bytes.resize(row * size_t(p.height));
    for (size_t y = 0; y < rows.size(); ++y) rows[y] = p.bytes.data() + y * row;
  }
  reader.readRows(rows.data());
  return p;
}

void openFile(PngReader& reader, const std::filesystem::path& file) {
  reader.state().file = std::fopen(file.c_str(), "rb");
  if (!reader.state().file) throw std::runtime_error(file.string() + ": cannot open: " + std::strerror(errno));
}

// encodePng's libpng calls (see PngState on setjmp).
bool encodeInto(PngState& s, int width, int height, int channels, int bits, png_bytep* rows, png_textp text,
                int ntext) {
  if (setjmp(png_jmpbuf(s.png))) return false;
  static const int kColourType[] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA, PNG_COLOR_TYPE_RGB,
                                    PNG_COLOR_TYPE_RGB_ALPHA};
  png_set_IHDR(s.png, s.info, png_uint_32(width), png_uint_32(height), bits, kColourType[channels - 1],
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_compression_level(s.png, kPngZlibLevel);
  png_set_filter(s.png, PNG_FILTER_TYPE_BASE, kPngFilter);
  if (ntext > 0) png_set_text(s.png, s.info, text, ntext);
  png_write_info(s.png, s.info);
  if (bits == 16) png_set_swap(s.png);  // PNG is big-endian
  png_write_image(s.png, rows);
  png_write_end(s.png, nullptr);
  return true;
}

}  // namespace

PngPixels readPngFile(const std::filesystem::path& file, const PngHeaderCheck& check) {
  PngReader reader(file.string());
  openFile(reader, file);
  return decodeWith(reader, check);
}

PngPixels decodePng(const std::uint8_t* data, size_t size, const std::string& what, const PngHeaderCheck& check) {
  PngReader reader(what);
  reader.state().data = data;
  reader.state().size = size;
  return decodeWith(reader, check);
}

ImageHeader readPngHeader(const std::filesystem::path& file) {
  PngReader reader(file.string());
  openFile(reader, file);
  int bits = 0;
  return reader.readHeader(bits);
}

std::string encodePng(int width, int height, int channels, int bits, const void* samples,
                      const std::vector<std::pair<std::string, std::string>>& text, const std::string& what) {
  if (width < 1 || height < 1 || channels < 1 || channels > 4 || (bits != 8 && bits != 16))
    throw std::runtime_error(what + ": cannot encode a " + std::to_string(width) + "x" + std::to_string(height) +
                             " PNG of " + std::to_string(channels) + " channels of " + std::to_string(bits) +
                             " bits (expected positive sizes, 1 to 4 channels, 8 or 16 bits)");
  std::string out;
  PngState s;
  s.out = &out;
  s.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &s, onError, onWarning);
  if (s.png) s.info = png_create_info_struct(s.png);
  struct Destroy {
    PngState& s;
    ~Destroy() { png_destroy_write_struct(&s.png, s.info ? &s.info : nullptr); }
  } destroy{s};
  if (!s.png || !s.info) throw std::runtime_error(what + ": cannot start libpng");
  png_set_write_fn(s.png, &s, writeBytes, flushBytes);
  const size_t row = size_t(width) * size_t(channels) * size_t(bits / 8);
  std::vector<png_bytep> rows(static_cast<size_t>(height));
  for (size_t y = 0; y < rows.size(); ++y)
    rows[y] = const_cast<png_bytep>(static_cast<const png_byte*>(samples)) + y * row;
  std::vector<png_text> chunks(text.size());
  for (size_t i = 0; i < text.size(); ++i) {
    chunks[i].compression = PNG_TEXT_COMPRESSION_NONE;
    chunks[i].key = const_cast<char*>(text[i].first.c_str());
    chunks[i].text = const_cast<char*>(text[i].second.c_str());
    chunks[i].text_length = text[i].second.size();
  }
  if (!encodeInto(s, width, height, channels, bits, rows.data(), chunks.data(), int(chunks.size())))
    throw std::runtime_error(what + ": cannot encode PNG: " + s.message);
  return out;
}

PngPixels requirePngDecodable(const std::string& png, const std::string& what, int width, int height) {
  return decodePng(reinterpret_cast<const std::uint8_t*>(png.data()), png.size(), what, [&](const ImageHeader& h) {
    if (h.width != width || h.height != height)
      throw std::runtime_error(what + ": the PNG just encoded decodes as " + std::to_string(h.width) + "x" +
                               std::to_string(h.height) + ", expected " + std::to_string(width) + "x" +
                               std::to_string(height));
  });
}

bool isPngSignature(const unsigned char* bytes, size_t size) { return size >= 8 && png_sig_cmp(bytes, 0, 8) == 0; }

const char* libpngVersion() { return PNG_LIBPNG_VER_STRING; }

}  // namespace xval
