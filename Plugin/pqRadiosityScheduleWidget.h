// ParaView panel for the lights' schedule (Radiosity Relight and Relit Surface): one row per
// keyframe under column headers (time, light, color, intensity, on), Add and Remove buttons;
// a typed cell is checked as the schedule file's rows are (vtkRadiosityLights::ReadScheduleRow).
#ifndef pqRadiosityScheduleWidget_h
#define pqRadiosityScheduleWidget_h

#include "pqRadiosityTableWidget.h"

class pqRadiosityScheduleWidget : public pqRadiosityTableWidget
{
  Q_OBJECT
  typedef pqRadiosityTableWidget Superclass;

public:
  // Rows: 7 per keyframe (time, light, r, g, b, intensity, enabled).
  pqRadiosityScheduleWidget(vtkSMProxy* proxy, vtkSMProperty* property, QWidget* parent = nullptr);

protected:
  void fillCell(int row, int column) override;
  /// A new keyframe: the last one a time step later, else the first light at time 0.
  QStringList newRow() const override;
  /// A typed cell into the rows; a row that does not read as a keyframe is put back.
  void cellEdited(int row, int column) override;

private:
  /// The first light's name the proxy knows of (its light names' information), else "0".
  QString firstLight() const;
};

#endif
