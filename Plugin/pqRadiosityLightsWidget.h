// ParaView panel for the relight filter's per-light settings: one row per light, by name,
// with a colour button, an intensity box and an on/off check box.
#ifndef pqRadiosityLightsWidget_h
#define pqRadiosityLightsWidget_h

#include "pqPropertyWidget.h"

#include <QVector>

class QTableWidget;
class vtkEventQtSlotConnect;

class pqRadiosityLightsWidget : public pqPropertyWidget
{
  Q_OBJECT
  typedef pqPropertyWidget Superclass;

public:
  pqRadiosityLightsWidget(vtkSMProxy* proxy, vtkSMProperty* property, QWidget* parent = nullptr);
  ~pqRadiosityLightsWidget() override;

  /// Sends the rows to the VTK object. The rows are written to the property directly,
  /// not through property links, so the links' accept alone would send nothing (and a
  /// display panel, which applies each change at once, would show none).
  void apply() override;

private Q_SLOTS:
  /// Rows for the lights the filter found (its LightNamesInfo), values from the property.
  void rebuild();

private:
  struct Light
  {
    QString Name;
    double Color[3] = { 1, 1, 1 };
    double Intensity = 1;
    bool Enabled = true;
    bool Edited = false;      ///< only edited lights are written, others keep their defaults
    bool ColorEdited = false; ///< an unedited colour is written as NaN: keep the default
  };
  void push();
  /// The table as tall as its rows (up to a limit), so the panel, not the table, scrolls.
  void fitHeight();
  void paintColorButton(int row);

  vtkSMProperty* Property;
  QTableWidget* Table;
  QVector<Light> Lights;
  vtkEventQtSlotConnect* Connection;
  bool Updating = false;
};

#endif
