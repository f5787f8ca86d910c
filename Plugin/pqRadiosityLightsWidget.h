// ParaView panel for the relight filter's per-light settings: one row per light, by name,
// with a color button, an intensity box and an on/off check box.
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
  /// A light as the panel shows it (name, color, intensity, on/off, and whether and how it
  /// was edited): only edited lights are written, an unedited color as NaN.
  using Light = vtkRadiosityLights::ShownLight;
  void push();
  /// The table as tall as its rows (up to a limit), so the panel, not the table, scrolls.
  void fitHeight();
  void paintColorButton(int row);
  /// The lights in effect (the information property), with the user's own rows on top.
  QVector<Light> readLights(vtkSMProperty* info) const;
  /// Same lights as shown: new values into the widgets, which someone may be typing in.
  void refreshInPlace(const QVector<Light>& lights);
  /// The name, color button, intensity box and on/off box of Lights[row].
  void addRow(int row);

  vtkSMProperty* Property;
  QTableWidget* Table;
  QVector<Light> Lights;
  vtkEventQtSlotConnect* Connection;
  bool Updating = false;
};

#endif
