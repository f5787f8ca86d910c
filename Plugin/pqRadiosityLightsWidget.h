// ParaView panel for the relight filter's per-light settings: one row per light, by name,
// and a column per part of the light's row as the row's declaration gives them (a color
// button, a number box, an on/off check box: vtkRadiosityLights::GetSettingRowColumnEditor).
#ifndef pqRadiosityLightsWidget_h
#define pqRadiosityLightsWidget_h

#include "pqRadiosityRowsWidget.h"
#include "vtkRadiosityLights.h" // the rows' face in the VTK layer

#include <QList>
#include <QStringList>
#include <QVariant>
#include <QVector>

class QTableWidget;
class vtkEventQtSlotConnect;

class pqRadiosityLightsWidget : public pqRadiosityRowsWidget
{
  Q_OBJECT
  typedef pqRadiosityRowsWidget Superclass;
  // Rows: name, r, g, b, intensity, enabled per edited light.

public:
  pqRadiosityLightsWidget(vtkSMProxy* proxy, vtkSMProperty* property, QWidget* parent = nullptr);
  ~pqRadiosityLightsWidget() override;

protected:
  void rowsSet() override { this->rebuild(); }

private Q_SLOTS:
  /// Rows for the lights the filter found (its LightNamesInfo), values from the property.
  void rebuild();

private:
  /// A light as the panel shows it (name, its row's values, which parts were edited): only
  /// edited lights are written, a part not edited as NaN.
  using Light = vtkRadiosityLights::ShownLight;
  void push();
  /// The table as tall as its rows (up to a limit), so the panel, not the table, scrolls.
  void fitHeight();
  void paintColorButton(int row, int column);
  /// The lights in effect (the information property), with the user's own rows on top.
  QVector<Light> readLights(vtkSMProperty* info) const;
  /// Same lights as shown: new values into the widgets, which someone may be typing in.
  void refreshInPlace(const QVector<Light>& lights);
  /// The name and one editor per part of Lights[row].
  void addRow(int row);
  /// The editor of the part shown in table column `column` of Lights[row].
  QWidget* makeEditor(int row, int column);
  /// Marks cells [first, end) of Lights[row] edited and sends the rows.
  void edited(int row, int first, int end);
  /// The first cell of each table column's part (the name's is 0), and past the last.
  QVector<int> PartStart;
  vtkSMProperty* Property;
  QTableWidget* Table;
  QVector<Light> Lights;
  vtkEventQtSlotConnect* Connection;
  bool Updating = false;
};

#endif
