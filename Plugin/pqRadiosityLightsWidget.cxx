#include "pqRadiosityLightsWidget.h"

#include "vtkRadiosityLights.h"

#include <algorithm>
#include <string>
#include <vector>

#include "vtkCommand.h"
#include "vtkEventQtSlotConnect.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMProxy.h"
#include "vtkSMStringVectorProperty.h"

#include <QCheckBox>
#include <QColorDialog>
#include <QDoubleSpinBox>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTableWidget>
#include <QVBoxLayout>

pqRadiosityLightsWidget::pqRadiosityLightsWidget(vtkSMProxy* proxy, vtkSMProperty* property, QWidget* parent)
  : Superclass(proxy, parent)
  , Property(property)
  , Table(new QTableWidget(0, 4, this))
  , Connection(vtkEventQtSlotConnect::New())
{
  this->setShowLabel(false);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(new QLabel("Lights (after the first Apply):", this));
  this->Table->setHorizontalHeaderLabels({ "Light", "Color", "Intensity", "On" });
  this->Table->verticalHeader()->hide();
  // The table fits the panel's width: names take what is left, and nothing hides past a
  // horizontal scroll bar (the panel is often narrower than the table would like).
  this->Table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
  for (int column = 1; column < 4; ++column)
  {
    this->Table->horizontalHeader()->setSectionResizeMode(column, QHeaderView::ResizeToContents);
  }
  this->Table->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  this->Table->setSelectionMode(QAbstractItemView::NoSelection);
  layout->addWidget(this->Table);
  // The names are known once the filter has run: rebuild after every update of the data.
  this->Connection->Connect(proxy, vtkCommand::UpdateDataEvent, this, SLOT(rebuild()));
  this->linkRows(property);
  this->rebuild();
}

pqRadiosityLightsWidget::~pqRadiosityLightsWidget()
{
  this->Connection->Disconnect();
  this->Connection->Delete();
}

namespace
{
std::vector<std::string> Strings(vtkSMProperty* property)
{
  vtkSMPropertyHelper helper(property);
  std::vector<std::string> strings;
  for (unsigned int i = 0; i < helper.GetNumberOfElements(); ++i)
  {
    strings.emplace_back(helper.GetAsString(i));
  }
  return strings;
}

std::vector<std::string> Strings(const QStringList& list)
{
  std::vector<std::string> strings;
  for (const QString& item : list)
  {
    strings.push_back(item.toStdString());
  }
  return strings;
}
} // namespace

QVector<pqRadiosityLightsWidget::Light> pqRadiosityLightsWidget::readLights(vtkSMProperty* info) const
{
  // The rows are read as the filters write them (vtkRadiosityLights::ShownLights), so a
  // new column is read there, not here.
  const std::vector<Light> shown = vtkRadiosityLights::ShownLights(Strings(info), Strings(this->Rows));
  return QVector<Light>(shown.begin(), shown.end());
}

void pqRadiosityLightsWidget::refreshInPlace(const QVector<Light>& lights)
{
  // Same lights: refresh the values in place (they may have been set from Python or
  // reset), without recreating the widgets someone may be typing in.
  this->Lights = lights;
  for (int row = 0; row < lights.size(); ++row)
  {
    if (auto* intensity = qobject_cast<QDoubleSpinBox*>(this->Table->cellWidget(row, 2)))
    {
      const QSignalBlocker block(intensity);
      intensity->setValue(lights[row].Intensity);
    }
    if (auto* enabled = qobject_cast<QCheckBox*>(this->Table->cellWidget(row, 3)))
    {
      const QSignalBlocker block(enabled);
      enabled->setChecked(lights[row].Enabled);
    }
    this->paintColorButton(row);
  }
}

void pqRadiosityLightsWidget::addRow(int row)
{
  const QVector<Light>& lights = this->Lights;
  auto* name = new QTableWidgetItem(QString::fromStdString(lights[row].Name));
  name->setFlags(Qt::ItemIsEnabled);
  this->Table->setItem(row, 0, name);

  auto* color = new QPushButton(this->Table);
  color->setMaximumWidth(48);
  this->Table->setCellWidget(row, 1, color);
  QObject::connect(color, &QPushButton::clicked, this, [this, row]() {
    Light& light = this->Lights[row];
    const QColor chosen = QColorDialog::getColor(
      QColor::fromRgbF(std::min(1.0, light.Color[0]), std::min(1.0, light.Color[1]), std::min(1.0, light.Color[2])),
      this, "Color of " + QString::fromStdString(light.Name));
    if (chosen.isValid())
    {
      light.Color[0] = chosen.redF();
      light.Color[1] = chosen.greenF();
      light.Color[2] = chosen.blueF();
      light.Edited = light.ColorEdited = true;
      this->paintColorButton(row);
      this->push();
    }
  });
  this->paintColorButton(row);

  auto* intensity = new QDoubleSpinBox(this->Table);
  intensity->setMaximumWidth(90);
  intensity->setRange(0.0, 1e9);
  intensity->setDecimals(3);
  intensity->setValue(lights[row].Intensity);
  this->Table->setCellWidget(row, 2, intensity);
  QObject::connect(intensity, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, [this, row](double v) {
    this->Lights[row].Intensity = v;
    this->Lights[row].Edited = true;
    this->push();
  });

  auto* enabled = new QCheckBox(this->Table);
  enabled->setChecked(lights[row].Enabled);
  this->Table->setCellWidget(row, 3, enabled);
  QObject::connect(enabled, &QCheckBox::toggled, this, [this, row](bool on) {
    this->Lights[row].Enabled = on;
    this->Lights[row].Edited = true;
    this->push();
  });
}

void pqRadiosityLightsWidget::rebuild()
{
  vtkSMProxy* proxy = this->proxy();
  proxy->UpdatePropertyInformation();
  // Values in effect (defaults included; the property's information property, on the
  // relight filter and on the Relit Surface representation alike), then the user's own
  // rows of the property, both as (name, r, g, b, intensity, enabled).
  vtkSMProperty* info = this->Property->GetInformationProperty();
  if (!info)
  {
    return;
  }
  const QVector<Light> lights = this->readLights(info);
  if (lights.size() == this->Lights.size() &&
    std::equal(lights.begin(), lights.end(), this->Lights.begin(),
      [](const Light& a, const Light& b) { return a.Name == b.Name; }))
  {
    this->refreshInPlace(lights);
    return;
  }
  this->Lights = lights;
  this->Updating = true;
  this->Table->setRowCount(lights.size());
  for (int row = 0; row < lights.size(); ++row)
  {
    this->addRow(row);
  }
  this->fitHeight();
  this->Updating = false;
}

void pqRadiosityLightsWidget::fitHeight()
{
  // A table that scrolls inside the scrolling panel shows rows cut off at its own frame,
  // where clicks land on the table or the panel and do nothing (found by TestGUI with 8
  // lights: the last three color buttons ignored clicks). Show every row up to 16, so
  // only the panel scrolls; beyond that the table scrolls as a visible list.
  constexpr int MostRowsShown = 16;
  int height = this->Table->horizontalHeader()->sizeHint().height() + 2 * this->Table->frameWidth();
  for (int row = 0; row < std::min(this->Table->rowCount(), MostRowsShown); ++row)
  {
    height += this->Table->rowHeight(row);
  }
  this->Table->setFixedHeight(height);
}

void pqRadiosityLightsWidget::paintColorButton(int row)
{
  auto* button = qobject_cast<QPushButton*>(this->Table->cellWidget(row, 1));
  const Light& light = this->Lights[row];
  // A default color is the light's Emission, often brighter than 1: its hue is shown.
  const double brightest = std::max({ light.Color[0], light.Color[1], light.Color[2], 1.0 });
  const QColor shown = QColor::fromRgbF(std::max(0.0, light.Color[0] / brightest),
    std::max(0.0, light.Color[1] / brightest), std::max(0.0, light.Color[2] / brightest));
  button->setText(QString());
  button->setStyleSheet(QString("background-color: %1").arg(shown.name()));
  button->setToolTip(light.ColorEdited ? QString("Color %1 (click to change)").arg(shown.name())
                                       : QString("The light's own color, from its Emission (click to change)"));
}

void pqRadiosityLightsWidget::push()
{
  if (this->Updating)
  {
    return;
  }
  QStringList rows;
  for (const Light& light : this->Lights)
  {
    if (!light.Edited)
    {
      continue;
    }
    for (const std::string& item : vtkRadiosityLights::EditedRow(light))
    {
      rows.push_back(QString::fromStdString(item));
    }
  }
  this->Rows = rows;
  Q_EMIT this->rowsChanged(); // the links set the property and say a change is available
}
