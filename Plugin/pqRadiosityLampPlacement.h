// Where a new lamp goes in the Mark Lights tables: just under the top of the input's box,
// facing down as the view shows the scene, and a name no light of the table or input has.
#ifndef pqRadiosityLampPlacement_h
#define pqRadiosityLampPlacement_h

#include <QString>
#include <QStringList>

class vtkPVDataInformation;
class vtkSMProxy;

namespace pqRadiosityLampPlacement
{
/// What ParaView knows of the data on the proxy's Input (null before it has run).
vtkPVDataInformation* InputInformation(vtkSMProxy* proxy);

/// A lamp's centre and the direction it faces (down), and the size of a twentieth of the
/// box's diagonal; a unit box about the origin before the input has run.
void CeilingSpot(vtkPVDataInformation* info, double centre[3], double facing[3], double& size);

/// The first of <stem>1, <stem>2, ... that neither `taken` nor the input's lights use.
QString UnusedName(const QString& stem, QStringList taken, vtkPVDataInformation* info);

/// A new lamp of the proxy's table as text: a free name, the CeilingSpot's centre and
/// facing (three numbers each), and its size.
struct NewLamp
{
  QString Name;
  QStringList Centre, Facing;
  QString Size;
};
NewLamp Place(vtkSMProxy* proxy, const QString& stem, const QStringList& taken);
}

#endif
