// What the relight filter, the GPU mapper and the writers all read of a solution's lights.
#ifndef vtkRadiosityLightDefaults_h
#define vtkRadiosityLightDefaults_h

#include "vtkRadiosityFiltersModule.h" // for export macro

#include <string> // for the names
#include <vector> // for the colors

class vtkFieldData;
class vtkPolyData;
namespace radiosity
{
struct Vec3;
}

/// The names in the field array LightNames, in order; empty when there is none.
VTKRADIOSITYFILTERS_EXPORT std::vector<std::string> vtkRadiosityLightNames(vtkFieldData* fields);

/// Each light's default color: the solver's LightDefaultColors when it holds one per light
/// (the cells are not read then), else each light's mean Emission over its cells
/// (radiosity::LightDefaultColors: zero stays zero; white without any).
VTKRADIOSITYFILTERS_EXPORT std::vector<radiosity::Vec3> vtkRadiosityLightDefaultColors(vtkPolyData* data, int lights);

/// 3 values a color, as vtkRadiosityCombineSolutions takes its weights.
VTKRADIOSITYFILTERS_EXPORT std::vector<double> vtkRadiosityFlatColors(const std::vector<radiosity::Vec3>& colors);

#endif
