// Stopping the radiosity filters from outside: ParaView's abort button, or a script.
#ifndef vtkRadiosityAbort_h
#define vtkRadiosityAbort_h

#include "vtkRadiosityFiltersModule.h" // for export macro

class vtkAlgorithm;

/// Asks every radiosity filter that is running to stop at its next progress report, as
/// vtkAlgorithm::AbortExecuteOn() does for one (the plugin's abort button calls this).
VTKRADIOSITYFILTERS_EXPORT void vtkRadiosityRequestAbort();

/// One execution's stop flag: true once `self` is told to abort, or once
/// vtkRadiosityRequestAbort() is called after this watch was made. Making the watch clears
/// the filter's own flag, which VTK 9.2's executive leaves set after an abort.
class VTKRADIOSITYFILTERS_EXPORT vtkRadiosityAbortWatch
{
public:
  explicit vtkRadiosityAbortWatch(vtkAlgorithm* self);
  bool Stop() const;

private:
  vtkAlgorithm* Self;
  unsigned Generation;
};

#endif
