// The luminaires a scene carries, as field arrays, one tuple a luminaire: LuminaireNames,
// LuminaireKinds and LuminaireParameters (strings), LuminairePlacement (10 doubles:
// position, aim, rotation in degrees, color). Mark Lights writes them, the mesher passes
// them on with the field data, the solver reads them. Private to the module.
#ifndef vtkRadiosityLuminaires_h
#define vtkRadiosityLuminaires_h

#include "Lights/Luminaires.h"

#include <string>
#include <vector>

class vtkFieldData;

namespace vtkRadiosityLuminaires
{
/// The rows in `fields` (none where it has no LuminaireNames); false with `error` where
/// the arrays disagree in length or type.
bool Read(vtkFieldData* fields, std::vector<radiosity::LuminaireRow>& rows, std::string& error);

/// Replaces the four arrays in `fields` by `rows` (removes them for none).
void Write(vtkFieldData* fields, const std::vector<radiosity::LuminaireRow>& rows);
}

#endif
