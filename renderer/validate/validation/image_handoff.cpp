// Images handed from a render job to its case's compare (image_handoff.h).
#include "validate/validation/image_handoff.h"

#include <sys/stat.h>

#include <utility>

namespace xval::validation {

namespace {
size_t pixelBytes(const Image& img) {
  size_t floats = img.rgba.size() + img.raw.size() + img.depth.size() + img.backfacing.size() +
                  img.incidence.size() + img.albedo.size() + img.texel_edge.size() + img.triangle_edge.size();
  for (const DiagnosticsChannel& c : kProbeChannels) floats += (img.*c.member).size();
  return floats * sizeof(float);
}
}  // namespace

std::optional<ImageHandoff::Identity> ImageHandoff::identityOf(const std::filesystem::path& file) {
  struct stat st {};
  if (::stat(file.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return std::nullopt;
  return Identity{static_cast<unsigned long long>(st.st_dev), static_cast<unsigned long long>(st.st_ino),
                  static_cast<unsigned long long>(st.st_size),
                  static_cast<long long>(st.st_mtim.tv_sec) * 1000000000ll + st.st_mtim.tv_nsec};
}

void ImageHandoff::put(const std::filesystem::path& file, Image image) {
  const std::optional<Identity> id = identityOf(file);
  if (!id) return;
  const size_t b = pixelBytes(image);
  std::lock_guard<std::mutex> hold(lock_);
  auto old = kept_.find(file);
  if (old != kept_.end()) bytes_ -= old->second.bytes, kept_.erase(old);
  if (bytes_ + b > max_bytes_) return;
  bytes_ += b;
  kept_.emplace(file, Kept{*id, std::move(image), b});
}

std::optional<Image> ImageHandoff::take(const std::filesystem::path& file) {
  std::optional<Kept> k;
  {
    std::lock_guard<std::mutex> hold(lock_);
    auto it = kept_.find(file);
    if (it == kept_.end()) return std::nullopt;
    bytes_ -= it->second.bytes;
    k = std::move(it->second);
    kept_.erase(it);
  }
  const std::optional<Identity> now = identityOf(file);
  if (!now || !(*now == k->identity)) return std::nullopt;
  return std::move(k->image);
}

size_t ImageHandoff::bytes() const {
  std::lock_guard<std::mutex> hold(lock_);
  return bytes_;
}

}  // namespace xval::validation
