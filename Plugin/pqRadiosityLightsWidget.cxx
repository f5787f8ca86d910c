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

namespace
{
/// The first cell of each part of a light's row (cells sharing a heading are one part),
/// and past the last: the panel's columns.
QVector<int> Parts()
{
  QVector<int> starts{ 0 };
  for (int c = 1; c < vtkRadiosityLights::GetSettingRowCells(); ++c)
  {
    if (std::string(vtkRadiosityLights::GetSettingRowColumnHeading(c)) !=
      vtkRadiosityLights::GetSettingRowColumnHeading(c - 1))
    {
      starts.push_back(c);
    }
  }
  starts.push_back(vtkRadiosityLights::GetSettingRowCells());
  return starts;
}
} // namespace

pqRadiosityLightsWidget::pqRadiosityLightsWidget(vtkSMProxy* proxy, vtkSMProperty* property, QWidget* parent)
  : Superclass(proxy, parent)
  , PartStart(Parts())
  , Property(property)
  , Table(new QTableWidget(0, static_cast<int>(this->PartStart.size()) - 1, this))
  , Connection(vtkEventQtSlotConnect::New())
{
  this->setShowLabel(false);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(new QLabel("Lights (after the first Apply):", this));
  QStringList headings;
  for (int column = 0; column + 1 < this->PartStart.size(); ++column)
  {
    headings.push_back(vtkRadiosityLights::GetSettingRowColumnHeading(this->PartStart[column]));
  }
  this->Table->setHorizontalHeaderLabels(headings);
  this->Table->verticalHeader()->hide();
  // The table fits the panel's width: names take what is left, and nothing hides past a
  // horizontal scroll bar (the panel is often narrower than the table would like).
  this->Table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
  for (int column = 1; column < headings.size(); ++column)
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
    for (int column = 1; column + 1 < this->PartStart.size(); ++column)
    {
      const double value = lights[row].Cells[this->PartStart[column]];
      QWidget* editor = this->Table->cellWidget(row, column);
      if (auto* number = qobject_cast<QDoubleSpinBox*>(editor))
      {
        const QSignalBlocker block(number);
        number->setValue(value);
      }
      else if (auto* flag = qobject_cast<QCheckBox*>(editor))
      {
        const QSignalBlocker block(flag);
        flag->setChecked(value != 0);
      }
      else
      {
        this->paintColorButton(row, column);
      }
    }
  }
}

void pqRadiosityLightsWidget::addRow(int row)
{
  auto* name = new QTableWidgetItem(QString::fromStdString(this->Lights[row].Name));
  name->setFlags(Qt::ItemIsEnabled);
  this->Table->setItem(row, 0, name);
  for (int column = 1; column + 1 < this->PartStart.size(); ++column)
  {
    this->Table->setCellWidget(row, column, this->makeEditor(row, column));
    if (vtkRadiosityLights::GetSettingRowColumnEditor(this->PartStart[column]) == vtkRadiosityLights::COLOR_CELL)
    {
      this->paintColorButton(row, column);
    }
  }
}

QWidget* pqRadiosityLightsWidget::makeEditor(int row, int column)
{
  const int first = this->PartStart[column], end = this->PartStart[column + 1];
  const double value = this->Lights[row].Cells[first];
  switch (vtkRadiosityLights::GetSettingRowColumnEditor(first))
  {
    case vtkRadiosityLights::COLOR_CELL:
    {
      auto* color = new QPushButton(this->Table);
      color->setMaximumWidth(48);
      QObject::connect(color, &QPushButton::clicked, this, [this, row, column, first, end]() {
        std::vector<double>& cells = this->Lights[row].Cells;
        const QColor chosen = QColorDialog::getColor(QColor::fromRgbF(std::min(1.0, cells[first]),
                                                       std::min(1.0, cells[first + 1]), std::min(1.0, cells[first + 2])),
          this, "Color of " + QString::fromStdString(this->Lights[row].Name));
        if (chosen.isValid())
        {
          cells[first] = chosen.redF();
          cells[first + 1] = chosen.greenF();
          cells[first + 2] = chosen.blueF();
          this->paintColorButton(row, column);
          this->edited(row, first, end);
        }
      });
      return color;
    }
    case vtkRadiosityLights::FLAG_CELL:
    {
      auto* flag = new QCheckBox(this->Table);
      flag->setChecked(value != 0);
      QObject::connect(flag, &QCheckBox::toggled, this, [this, row, first, end](bool on) {
        this->Lights[row].Cells[first] = on ? 1.0 : 0.0;
        this->edited(row, first, end);
      });
      return flag;
    }
    default:
    {
      auto* number = new QDoubleSpinBox(this->Table);
      number->setMaximumWidth(90);
      number->setRange(vtkRadiosityLights::GetSettingRowColumnLow(first), vtkRadiosityLights::GetSettingRowColumnHigh(first));
      number->setDecimals(3);
      number->setValue(value);
      QObject::connect(number, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this,
        [this, row, first, end](double v) {
          this->Lights[row].Cells[first] = v;
          this->edited(row, first, end);
        });
      return number;
    }
  }
}

void pqRadiosityLightsWidget::edited(int row, int first, int end)
{
  Light& light = this->Lights[row];
  std::fill(light.CellEdited.begin() + first, light.CellEdited.begin() + end, 1);
  light.Edited = true;
  this->push();
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

void pqRadiosityLightsWidget::paintColorButton(int row, int column)
{
  auto* button = qobject_cast<QPushButton*>(this->Table->cellWidget(row, column));
  if (!button)
  {
    return;
  }
  const int first = this->PartStart[column];
  const Light& light = this->Lights[row];
  const double* rgb = light.Cells.data() + first;
  // A default color is the light's Emission, often brighter than 1: its hue is shown.
  const double brightest = std::max({ rgb[0], rgb[1], rgb[2], 1.0 });
  const QColor shown = QColor::fromRgbF(
    std::max(0.0, rgb[0] / brightest), std::max(0.0, rgb[1] / brightest), std::max(0.0, rgb[2] / brightest));
  button->setText(QString());
  button->setStyleSheet(QString("background-color: %1").arg(shown.name()));
  button->setToolTip(light.CellEdited[first] ? QString("Color %1 (click to change)").arg(shown.name())
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
