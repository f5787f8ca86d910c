// Every rank's polydata piece on every rank, sent as raw arrays. VTK's own
// vtkMultiProcessController::AllGather of data objects writes each piece as a legacy VTK
// file and parses it back on every rank: 0.27 s of a 8.6 s solve on 2 ranks at 217,800
// elements, all of it repeated work. Not wrapped.
#ifndef vtkRadiosityGather_h
#define vtkRadiosityGather_h

#include "vtkSmartPointer.h"

#include <vector>

class vtkMultiProcessController;
class vtkPolyData;

namespace vtkRadiosityGather
{

/// Rank r's `piece` (null for an empty one) as `pieces[r]` on every rank: points, the four
/// cell arrays, every named point and cell array and the field data. A rank's own entry
/// is its piece itself, not a copy. Returns true where the arrays
/// went raw, false where some piece needed VTK's general gather (string, bit or non-AOS
/// arrays). A failed transfer ends the job with the reason (the ranks would be out of step).
bool AllGatherPieces(
  vtkMultiProcessController* controller, vtkPolyData* piece, std::vector<vtkSmartPointer<vtkPolyData>>& pieces);

}

#endif
