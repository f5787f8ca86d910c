// Luminaires as a scene carries them from the light marker to the solver: a row each,
// naming its kind and giving that kind's parameters as text ("file=a.ies; lumens=1200"),
// so a new kind or parameter needs no new array (the VTK layer's field arrays
// LuminaireNames, LuminaireKinds, LuminaireParameters, LuminairePlacement hold the rows).
#ifndef RadiosityCore_Luminaires_h
#define RadiosityCore_Luminaires_h

#include "Lights/PointLight.h"

#include <string>
#include <vector>

namespace radiosity
{

struct LuminaireRow
{
  std::string Name;
  std::string Kind = "goniometric";
  std::string Parameters; ///< "name=value" pairs separated by ';'
  Vec3 Position;
  Vec3 Aim{ 0, 0, -1 };
  double Rotation = 0; ///< degrees about the aim
  Vec3 Color{ 1, 1, 1 };
};

/// The numbers of LuminairePlacement per row: position, aim, rotation, color.
constexpr int kLuminairePlacementValues = 10;

/// "name=value; name=value" into `out`; empty, or what is wrong (a pair without '=', a
/// name given twice).
std::string ParseLightParameters(const std::string& text, LightParameters& out);

/// The light `row` describes (its kind made from its parameters, placed and colored);
/// empty, or the problem prefixed with "luminaire '<name>': ".
std::string MakePointLight(const LuminaireRow& row, PointLight& out);

/// Empty, or why the rows cannot stand beside each other and the scene's own lights
/// (`taken`): names must be unique, [A-Za-z0-9_]+, as every light's are.
std::string LuminaireNamesProblem(const std::vector<LuminaireRow>& rows, const std::vector<std::string>& taken);

} // namespace radiosity

#endif
