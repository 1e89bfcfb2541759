// A job's refusal and export in one: the refusal of a renderer that
// exports (Renderer::exporter) is decided by writing the export its render
// reads into the job's work folder, and that export is handed on to the
// render (RenderRequest::exported), so a job exports its scene once.
//
// Through the export cache (renderers/export_cache.h) when the request has
// an inputs key: the refusal is stored under refusalKey (the renderer's id,
// its definition file's bytes, the scene's inputs), the export under the
// exporter's name (renderers of one exporter share it). A refusal read
// back writes no export; an export restored says it is not refused only
// after the renderer's own check passed.
#pragma once

#include <string>

#include "renderers/renderer.h"

namespace xval::renderers {

// Why `renderer` cannot express the scene ("" when it can). For a renderer
// with an exporter, "" means request.work_dir (a folder the caller made,
// empty) now holds the export and request.exported is set; a refusal may
// leave there what the exporter wrote before it refused. Other renderers:
// cannot_express's ("" without one). Errors other than a refusal (a full
// disk, an unreadable definition file) propagate.
std::string refuseOrExport(const Renderer& renderer, const Scene& scene, RenderRequest& request);

// The inputs key of a renderer's refusal: SHA-256 of the scene's inputs key,
// the renderer's id and, for a renderer defined by a file, that file's
// bytes (a changed definition is a new key; for a golden set, golden-NAME,
// NAME's file, whose refusals it takes); "" for an empty inputs key.
std::string refusalKey(const Renderer& renderer, const std::string& inputs_key);

}  // namespace xval::renderers
