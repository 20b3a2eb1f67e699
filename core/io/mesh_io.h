#pragma once
// Reading stones from the formats cut designers use. Each parser takes the file's bytes (not a path) so it
// can be tested and fuzzed; loadStone() reads a file, picks the parser and builds the Stone.
#include <optional>
#include <string>
#include <string_view>

#include "geometry/polygon_mesh.h"
#include "stone/stone.h"

namespace facetlight {

enum class MeshFormat { Obj, Stl, GemCad, GemCadBinary };

// Wavefront OBJ: polygons of any size; g/o/usemtl names become polygon names.
PolygonMesh parseObj(std::string_view text, const MeshLimits& limits = {});
// STL, binary (84 + 50 n bytes, even when it begins with "solid") or ASCII.
PolygonMesh parseStl(std::string_view bytes, const MeshLimits& limits = {});
// GemCad .asc design: tiers of facet planes, intersected as half-spaces; polygon names from tier names.
PolygonMesh parseGemCad(std::string_view text, const MeshLimits& limits = {});
// Whether the bytes begin as a GemCad binary .gem does (it has no signature: its first facet record's shape).
bool looksLikeGemCadBinary(std::string_view bytes);

// The format from a file name's extension (.obj, .stl, .asc, .gem), if it has a known one.
std::optional<MeshFormat> formatFromFileName(std::string_view fileName);
// The format from the content itself, for uploads without a trustworthy name.
MeshFormat detectFormat(std::string_view bytes);
PolygonMesh parseMesh(std::string_view bytes, MeshFormat format, const MeshLimits& limits = {});

// Reads and builds a stone from a file; its name is the file's stem. Throws Error with the path on failure.
Stone loadStone(const std::string& path, const StoneOptions& options = {});

}  // namespace facetlight
