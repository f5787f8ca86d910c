// Wavefront OBJ and MTL text into a RawScene. VTK's OBJ reader (9.2) is not used for
// scenes: it assigns material ids only to faces with texture coordinates, drops faces
// whose texture or normal indices are incomplete, and ignores `o` object names.
#ifndef RadiosityCore_Wavefront_h
#define RadiosityCore_Wavefront_h

#include "Import/SceneImport.h"

#include <string>
#include <vector>

namespace radiosity
{

/// Parses OBJ text: `v` (extra color or w values ignored), `f` with any of v, v/vt,
/// v//vn, v/vt/vn and negative (relative) indices, `usemtl`, `mtllib`, `o` and `g`;
/// other statements are ignored. Polygons get the material named by the last `usemtl`
/// (an index into raw.Materials, which lists the names in order of first use, colors
/// still at their defaults) and the object of the last `o` or `g`. Returns an empty
/// string or "line N: what is wrong".
std::string ParseObj(const std::string& text, RawScene& raw, std::vector<std::string>& libraries);

/// Parses MTL text, appending its materials to `materials`: `newmtl`, `Kd`, `Ke` and
/// `map_Kd`, the rest ignored. A name already there keeps its first definition (assimp
/// writes some twice). Returns an empty string or "line N: what is wrong".
std::string ParseMtl(const std::string& text, std::vector<ImportMaterial>& materials);

} // namespace radiosity

#endif
