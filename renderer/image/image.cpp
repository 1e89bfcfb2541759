// Image's diagnostics copy (image/image.h).
#include "image/image.h"

namespace xval {

void copyDiagnostics(const Image& from, Image& to) {
  to.depth = from.depth;
  to.backfacing = from.backfacing;
  to.incidence = from.incidence;
  to.texel_edge = from.texel_edge;
  to.triangle_edge = from.triangle_edge;
  for (const DiagnosticsChannel& c : kProbeChannels) to.*c.member = from.*c.member;
}

}  // namespace xval
