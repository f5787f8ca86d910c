// ParaView panel for the relight filter's per-light settings: one row per light, by name,
// with a color button, an intensity box and an on/off check box.
#ifndef pqRadiosityLightsWidget_h
#define pqRadiosityLightsWidget_h

#include "pqPropertyWidget.h"

#include <QList>
#include <QStringList>
#include <QVariant>
#include <QVector>

class QTableWidget;
class vtkEventQtSlotConnect;

class pqRadiosityLightsWidget : public pqPropertyWidget
{
  Q_OBJECT
  typedef pqPropertyWidget Superclass;
  /// The property's elements (name, r, g, b, intensity, enabled per edited light), linked
  /// to it through ParaView's property links: Apply, Reset and undo work as for any panel
  /// widget, and a display panel applies each change at once.
  Q_PROPERTY(QList<QVariant> rows READ rows WRITE setRows NOTIFY rowsChanged)

public:
  pqRadiosityLightsWidget(vtkSMProxy* proxy, vtkSMProperty* property, QWidget* parent = nullptr);
  ~pqRadiosityLightsWidget() override;

  QList<QVariant> rows() const;
  void setRows(const QList<QVariant>& values);

Q_SIGNALS:
  void rowsChanged();

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
    bool ColorEdited = false; ///< an unedited color is written as NaN: keep the default
  };
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
  QStringList Rows; ///< the property's elements as the links last gave or took them
  QTableWidget* Table;
  QVector<Light> Lights;
  vtkEventQtSlotConnect* Connection;
  bool Updating = false;
};

#endif
