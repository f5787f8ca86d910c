// From what a scene file holds (polygons, materials, objects) to the radiosity input:
// reflectance from diffuse colors, lights from emissive materials, degenerate cells out.
// File formats are read elsewhere (VTK's readers, assimp); this part is format-free.
#ifndef RadiosityCore_SceneImport_h
#define RadiosityCore_SceneImport_h

#include "Geometry/Scene.h"

#include <string>
#include <vector>

namespace radiosity
{

/// A surface material as a file describes it.
struct ImportMaterial
{
  std::string Name;
  Vec3 Diffuse{ 0.8, 0.8, 0.8 }; ///< linear RGB, as written (clamped later)
  Vec3 Emissive;                 ///< emitted color; any positive channel makes a light
  std::string DiffuseTexture;    ///< texture file the diffuse color is multiplied by, if any
  std::string EmissiveTexture;   ///< texture file the emitted color is multiplied by, if any
};

/// Polygons as read from a file, before they become a radiosity scene.
struct RawScene
{
  std::vector<Vec3> Points;
  std::vector<int> Offsets{ 0 };
  std::vector<int> Connectivity;
  std::vector<int> Material; ///< per polygon: index into Materials, or -1 for none
  std::vector<int> Object;   ///< per polygon: index into ObjectNames, or -1
  std::vector<Vec3> Color;  ///< per polygon, multiplies its material's diffuse; empty: none
  std::vector<ImportMaterial> Materials;
  std::vector<std::string> ObjectNames;
  /// How finely the source gave the coordinates (float data: its spacing at the farthest
  /// point; 0 for double): see SceneMesh::PointQuantum.
  double PointQuantum = 0;
  int NumberOfPolygons() const { return static_cast<int>(Offsets.size()) - 1; }
};

struct ImportOptions
{
  double UnitScale = 1.0;      ///< multiplies every coordinate (0.001: millimetres to metres)
  bool LightsPerObject = false; ///< one light per object's emissive material, not per material
};

/// The radiosity input: the mesh (reflectance and light ids set), each light's emission
/// and name, and each polygon's material for choosing cells by material later.
struct ImportedScene
{
  SceneMesh Mesh;
  std::vector<Vec3> Emission; ///< per polygon
  std::vector<std::string> LightNames;
  std::vector<int> Material; ///< per polygon, into MaterialNames
  std::vector<std::string> MaterialNames;
  int Dropped = 0;                   ///< degenerate polygons left out
  std::vector<std::string> Warnings; ///< clamped materials, dropped cells, no lights
  std::string Summary;               ///< polygons, materials, lights, dropped cells
};

/// The warning for a scene without lights, which Mark Lights takes back once it makes one.
constexpr const char* NoLightsWarning = "no emissive material: mark lights before solving";

/// Builds the scene; returns an empty string or what makes the file unusable (a
/// non-finite coordinate, a material color that is not a number, nothing left).
std::string BuildImportedScene(const RawScene& raw, const ImportOptions& options, ImportedScene& out);

} // namespace radiosity

#endif
