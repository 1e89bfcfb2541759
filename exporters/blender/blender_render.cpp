#include "blender/blender_render.h"

#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>

#include "process/run_process.h"
#include "common/supersample.h"
#include "gltf/gltf_exporter.h"
#include "image/image_header.h"

namespace xval {

namespace OIIO = OIIO_NAMESPACE;

std::filesystem::path blenderScript() {
  if (const char* env = std::getenv("XVAL_BLENDER_SCRIPT")) return env;
  return XVAL_BLENDER_SCRIPT_DEFAULT;
}

namespace {

// The diffuse-direct pass of a multilayer EXR (channels "<layer>.DiffDir.R"
// ...), with alpha from the combined pass.
Image readDiffDir(const std::filesystem::path& file, int width, int height) {
  requireRegularImageFile(file);
  auto in = OIIO::ImageInput::open(file.string());
  if (!in) throw ExternalToolError(file.string() + ": cannot open: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  // The header must claim the camera's size before any pixel is allocated.
  const std::string problem =
      imageHeaderProblem({spec.width, spec.height, spec.depth, spec.nchannels}, readImageLimits(width, height));
  if (!problem.empty()) throw ExternalToolError(file.string() + ": the image " + problem);
  const int nc = spec.nchannels;
  std::vector<float> buf(size_t(spec.width) * spec.height * nc);
  if (!in->read_image(0, 0, 0, nc, OIIO::TypeDesc::FLOAT, buf.data()))
    throw ExternalToolError(file.string() + ": cannot read: " + in->geterror());
  auto find = [&](const std::string& suffix) {
    for (int i = 0; i < nc; ++i) {
      const std::string& n = spec.channelnames[i];
      if (n.size() >= suffix.size() && n.compare(n.size() - suffix.size(), suffix.size(), suffix) == 0)
        return i;
    }
    throw ExternalToolError(file.string() + ": no channel *" + suffix);
  };
  int ch[4] = {find("DiffDir.R"), find("DiffDir.G"), find("DiffDir.B"), find("Combined.A")};
  Image img(spec.width, spec.height, false);
  for (size_t i = 0; i < size_t(spec.width) * spec.height; ++i)
    for (int c = 0; c < 4; ++c) img.rgba[i * 4 + c] = buf[i * nc + ch[c]];
  return img;
}

// Blender prints " Time: MM:SS.ss (Saving: ...)" after a render.
double renderTimeFromLog(const std::filesystem::path& log) {
  std::ifstream in(log);
  std::string line;
  double found = -1.0;
  while (std::getline(in, line)) {
    auto at = line.find(" Time: ");
    int mm;
    double ss;
    if (at != std::string::npos && std::sscanf(line.c_str() + at, " Time: %d:%lf", &mm, &ss) == 2)
      found = mm * 60.0 + ss;
  }
  return found;
}

}  // namespace

void checkBlenderScene(const Scene& scene, BlenderEngine engine) {
  // render.spp = n^2: Blender renders n W x n H pixels, one sample through
  // each centre (common/supersample.h); the grid's limits are the harness's.
  subpixelGrid(scene);
  // EEVEE's Image Texture, Linear, is trilinear on the GPU; Cycles has no
  // such lookup.
  if (engine == BlenderEngine::Cycles)
    refuseTrilinear(scene, "blender (Cycles)",
                    "Cycles filters an image texture on its one level (Linear is bilinear, no mip-maps on the "
                    "CPU) and a path-traced ray carries no pixel footprint to choose a level from");
}

Image renderWithBlender(const Scene& scene, const std::filesystem::path& work_dir,
                        double timeout_seconds, ExternalRenderInfo* info, BlenderMode mode,
                        BlenderEngine engine) {
  if (engine == BlenderEngine::Eevee && mode != BlenderMode::Model)
    throw std::invalid_argument("renderWithBlender: EEVEE renders the model mode only");
  // Checked before anything is written.
  checkBlenderScene(scene, engine);
  const SubpixelGrid g = subpixelGrid(scene);
  const std::filesystem::path script = blenderScript();
  if (!std::filesystem::is_regular_file(script))
    throw ExternalToolError("Blender script " + script.string() +
                            " not found (set XVAL_BLENDER_SCRIPT)");
  // Blender reads '\\' in a path as a folder separator: such a path would
  // make it read or write elsewhere.
  const std::filesystem::path abs_work = std::filesystem::absolute(work_dir);
  for (const auto& p : {abs_work, std::filesystem::absolute(script)})
    if (p.string().find('\\') != std::string::npos)
      throw ExternalToolError(p.string() + ": contains '\\', which Blender reads as a folder separator; "
                              "choose a folder without it");
  GltfExport ex = exportGltf(scene, work_dir);
  // The image's name is this attempt's own: a Blender left from an earlier
  // attempt cannot supply it.
  const std::string tool = engine == BlenderEngine::Eevee ? "eevee" : "blender";
  const std::filesystem::path out = abs_work / (tool + "-" + attemptToken() + ".exr");
  const std::filesystem::path log = work_dir / (tool + ".log");
  ProcessResult r = runProcess(
      {"blender", "-b", "--factory-startup", "-noaudio", "-P", std::filesystem::absolute(script).string(),
       "--", "--gltf", std::filesystem::absolute(ex.gltf).string(), "--out", out.string(),
       "--mode", mode == BlenderMode::Model ? "model" : "native-lambert",
       "--engine", engine == BlenderEngine::Eevee ? "eevee" : "cycles"},
      work_dir, log, timeout_seconds);
  if (info) *info = {r.seconds, log, renderTimeFromLog(log)};
  requireToolOutput(tool, ex.gltf, r, out);
  Image fine;
  try {
    fine = mode == BlenderMode::Model ? readImage(out, g.width, g.height) : readDiffDir(out, g.width, g.height);
  } catch (const std::exception& e) {
    throw ExternalToolError(tool + " wrote an unusable image: " + e.what());
  }
  requireImageSize(tool, fine, g.width, g.height);
  requireFinite(tool, fine);
  // The EXR holds each sample unsaturated: keep it as raw for the box
  // filter's unsaturated mean.
  fine.raw.resize(size_t(fine.width) * fine.height * 3);
  for (size_t i = 0; i < size_t(fine.width) * fine.height; ++i)
    for (int c = 0; c < 3; ++c) fine.raw[i * 3 + c] = fine.rgba[i * 4 + c];
  // Model: each sample saturated, as the reference renderer's, then
  // averaged (boxFilter).
  Image img = boxFilter(fine, g.n);
  if (mode == BlenderMode::NativeLambert) {
    // The diffuse-direct pass is compared unsaturated (a physical
    // quantity): the unsaturated mean.
    for (size_t i = 0; i < size_t(img.width) * img.height; ++i)
      for (int c = 0; c < 3; ++c) img.rgba[i * 4 + c] = img.raw[i * 3 + c];
    img.raw.clear();
  }
  return img;
}

}  // namespace xval
