// Stopping the radiosity filters from outside: ParaView's abort button, or a script.
#ifndef vtkRadiosityAbort_h
#define vtkRadiosityAbort_h

#include "vtkRadiosityFiltersModule.h" // for export macro

class vtkAlgorithm;

/// Asks every radiosity filter to stop at its next progress report, as
/// vtkAlgorithm::AbortExecuteOn() does for one, until vtkRadiosityClearAbort(): the
/// plugin's abort button requests, and clears when ParaView's update ends, so that a
/// click during the mesher's last report also stops the solver after it.
VTKRADIOSITYFILTERS_EXPORT void vtkRadiosityRequestAbort();
VTKRADIOSITYFILTERS_EXPORT void vtkRadiosityClearAbort();

/// One execution's stop flag: true once `self` is told to abort, or while an abort is
/// requested. Making the watch clears the filter's own flag, which VTK 9.2's executive
/// leaves set after an abort.
class VTKRADIOSITYFILTERS_EXPORT vtkRadiosityAbortWatch
{
public:
  explicit vtkRadiosityAbortWatch(vtkAlgorithm* self);
  bool Stop() const;

private:
  vtkAlgorithm* Self;
};

#endif
