// The plumbing every filter of this module shares, written once: the first input and the
// output, ParaView's MPI ranks, and a guard around the filter's own work (no exception
// escapes, a failure empties and marks the output, one rank's failure fails them all).
#ifndef vtkRadiosityAlgorithm_h
#define vtkRadiosityAlgorithm_h

#include "vtkPolyDataAlgorithm.h"
#include "vtkRadiosityFiltersModule.h" // for export macro
#include "vtkSmartPointer.h"           // for the input

class vtkMultiProcessController;

class VTKRADIOSITYFILTERS_EXPORT vtkRadiosityAlgorithm : public vtkPolyDataAlgorithm
{
public:
  vtkTypeMacro(vtkRadiosityAlgorithm, vtkPolyDataAlgorithm);

protected:
  vtkRadiosityAlgorithm() = default;
  ~vtkRadiosityAlgorithm() override = default;

  /// What one execution works on.
  struct Run
  {
    vtkSmartPointer<vtkPolyData> Input;    ///< the first input as polygons; null without one
    vtkPolyData* Output = nullptr;         ///< the first output
    vtkMultiProcessController* Parallel = nullptr; ///< ParaView's MPI server's ranks, else null
    vtkInformationVector** Inputs = nullptr;       ///< every input, for filters of more
    vtkInformationVector* Outputs = nullptr;       ///< every output, for filters of more
  };

  /// Takes the run's data and calls Execute inside vtkRadiosityAdapter::Guarded.
  int RequestData(vtkInformation*, vtkInformationVector** inputs, vtkInformationVector* outputs) final;
  /// The filter's own work: 1, or 0 after saying why.
  virtual int Execute(const Run& run) = 0;
  /// Clears what the last execution left outside the first output (a second output, the
  /// lights it reports), before the guard: it runs even where Execute does not.
  virtual void BeforeRun(const Run&) {}
  /// The first input as polygons (a filter that takes any data set converts it here).
  virtual vtkSmartPointer<vtkPolyData> InputOf(vtkInformationVector** inputs);
  /// Whether the guard refuses an input an upstream filter failed before Execute runs. Not
  /// where the ranks must all reach a collective first (they take it up themselves).
  virtual bool GuardsInput(const Run& run);
  /// Whether the ranks of ParaView's MPI server agree on failure (one fails, all fail):
  /// for the filters whose work meets in collectives; one that works on its own piece
  /// alone must not wait for the others.
  virtual bool AgreesAcrossRanks() const { return true; }

private:
  vtkRadiosityAlgorithm(const vtkRadiosityAlgorithm&) = delete;
  void operator=(const vtkRadiosityAlgorithm&) = delete;
};

#endif
