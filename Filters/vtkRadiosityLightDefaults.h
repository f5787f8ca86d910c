// The lights' default colours as the relight filter and the GPU mapper both read them.
#ifndef vtkRadiosityLightDefaults_h
#define vtkRadiosityLightDefaults_h

#include "vtkRadiosityFiltersModule.h" // for export macro

#include <vector> // for the colours

class vtkPolyData;

/// 3 values per light: the solver's LightDefaultColors when it holds one per light, else
/// each light's mean Emission over its cells (zero stays zero; white without any).
VTKRADIOSITYFILTERS_EXPORT std::vector<double> vtkRadiosityDefaultLightColours(vtkPolyData* data, int lights);

#endif
