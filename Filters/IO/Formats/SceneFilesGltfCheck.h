// What a glTF file says about its own data, held against that data (SceneFilesGltfCheck.cxx).
#ifndef SceneFilesGltfCheck_h
#define SceneFilesGltfCheck_h

#include <vtk_nlohmannjson.h>
#include VTK_NLOHMANN_JSON(json.hpp)

#include <string>

namespace SceneFiles
{

/// Empty when every index in `document` names an item that exists, every buffer holds the
/// bytes it claims (files in the model's folder, or a .glb's binary chunk of `glbBinary`
/// bytes; -1 for a .gltf), every range fits its buffer and the nodes form a forest;
/// otherwise what is wrong, as a phrase ("buffer 0 claims 3600 bytes and holds 36").
std::string CheckGltfReferences(const nlohmann::json& document, const std::string& path, long long glbBinary);

}

#endif
