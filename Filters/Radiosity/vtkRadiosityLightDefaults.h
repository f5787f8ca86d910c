// What the relight filter, the GPU mapper and the writers all read of a solution's lights.
#ifndef vtkRadiosityLightDefaults_h
#define vtkRadiosityLightDefaults_h

#include "vtkRadiosityFiltersModule.h" // for export macro

#include <string> // for the names
#include <vector> // for the colors

class vtkFieldData;
class vtkPolyData;

/// The names in the field array LightNames, in order; empty when there is none.
VTKRADIOSITYFILTERS_EXPORT std::vector<std::string> vtkRadiosityLightNames(vtkFieldData* fields);

/// 3 values per light: the solver's LightDefaultColors when it holds one per light, else
/// each light's mean Emission over its cells (zero stays zero; white without any).
VTKRADIOSITYFILTERS_EXPORT std::vector<double> vtkRadiosityLightDefaultColors(vtkPolyData* data, int lights);

#endif
