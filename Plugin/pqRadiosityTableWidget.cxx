#include "pqRadiosityTableWidget.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QRegularExpression>
#include <QSignalBlocker>
#include <QScrollBar>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <functional>

pqRadiosityTableWidget::pqRadiosityTableWidget(vtkSMProxy* proxy, const Design& design, QWidget* parent)
  : Superclass(proxy, parent)
  , Table(new QTableWidget(0, design.Headers.size(), this))
  , Starts(design.Starts)
  , PerRow(design.Starts.back())
{
  this->setShowLabel(false);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(new QLabel(design.Title, this));
  this->Table->setObjectName(design.TableName);
  this->Table->setHorizontalHeaderLabels(design.Headers);
  for (int column = 0; column < design.Tips.size() && column < design.Headers.size(); ++column)
  {
    this->Table->horizontalHeaderItem(column)->setToolTip(design.Tips[column]);
  }
  this->Table->verticalHeader()->hide();
  this->Table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  this->Table->setSelectionBehavior(QAbstractItemView::SelectRows);
  layout->addWidget(this->Table);
  auto* buttons = new QHBoxLayout();
  auto* add = new QPushButton(design.AddText, this);
  add->setObjectName(design.AddName);
  auto* remove = new QPushButton("Remove", this);
  remove->setObjectName(design.RemoveName);
  buttons->addWidget(add);
  buttons->addWidget(remove);
  buttons->addStretch();
  layout->addLayout(buttons);
  QObject::connect(add, &QPushButton::clicked, this, &pqRadiosityTableWidget::addRow);
  QObject::connect(remove, &QPushButton::clicked, this, &pqRadiosityTableWidget::removeRows);
  QObject::connect(this->Table, &QTableWidget::cellChanged, this, [this](int row, int column) {
    if (!this->Filling)
    {
      this->cellEdited(row, column);
    }
  });
}

QStringList pqRadiosityTableWidget::names() const
{
  QStringList first;
  for (int k = 0; k < this->Rows.size(); k += this->PerRow)
  {
    first << this->Rows[k];
  }
  return first;
}

QStringList pqRadiosityTableWidget::typed(int row, int column, bool text) const
{
  const QTableWidgetItem* item = this->Table->item(row, column);
  const QString typed = item ? item->text().trimmed() : QString();
  return text ? QStringList{ typed } : typed.split(QRegularExpression("[,;\\s]+"), Qt::SkipEmptyParts);
}

bool pqRadiosityTableWidget::numbers(const QStringList& parts, int column, double low) const
{
  bool usable = parts.size() == this->count(column);
  for (int k = 0; usable && k < parts.size(); ++k)
  {
    bool number = false;
    const double value = parts[k].toDouble(&number);
    usable = number && std::isfinite(value) && value >= low;
  }
  return usable;
}

bool pqRadiosityTableWidget::direction(const QStringList& parts)
{
  return parts.size() == 3 && (parts[0].toDouble() != 0 || parts[1].toDouble() != 0 || parts[2].toDouble() != 0);
}

void pqRadiosityTableWidget::takeOrPutBack(int row, int column, const QStringList& parts, bool usable)
{
  QTableWidgetItem* item = this->Table->item(row, column);
  if (!usable)
  {
    const QSignalBlocker block(this->Table);
    if (item)
    {
      item->setText(this->cell(row, column).join(", ")); // what it held
    }
    return;
  }
  std::copy(parts.begin(), parts.end(), this->Rows.begin() + this->at(row, column));
  Q_EMIT this->rowsChanged();
}

void pqRadiosityTableWidget::addRow()
{
  const QStringList added = this->newRow();
  if (added.isEmpty())
  {
    return; // nothing left to add
  }
  this->Rows << added;
  this->fill();
  Q_EMIT this->rowsChanged();
}

void pqRadiosityTableWidget::removeRows()
{
  QList<int> rows;
  for (const QModelIndex& index : this->Table->selectionModel()->selectedRows())
  {
    rows << index.row();
  }
  if (rows.isEmpty() && this->Table->rowCount() > 0)
  {
    rows << this->Table->rowCount() - 1; // nothing selected: the last entry
  }
  if (rows.isEmpty())
  {
    return; // no entry: nothing changes, nothing to Apply
  }
  std::sort(rows.begin(), rows.end(), std::greater<int>());
  for (int row : rows)
  {
    for (int k = 0; k < this->PerRow; ++k)
    {
      this->Rows.removeAt(row * this->PerRow);
    }
  }
  this->fill();
  Q_EMIT this->rowsChanged();
}

void pqRadiosityTableWidget::fill()
{
  this->Filling = true;
  const int entries = static_cast<int>(this->Rows.size()) / this->PerRow;
  this->Table->setRowCount(entries);
  for (int row = 0; row < entries; ++row)
  {
    for (int column = 0; column < this->Table->columnCount(); ++column)
    {
      this->fillCell(row, column);
    }
  }
  this->Filling = false;
  this->fitHeight();
}

void pqRadiosityTableWidget::fitHeight()
{
  // Several columns rarely fit the panel's width: room for the horizontal scroll bar too.
  this->Table->resizeRowsToContents();
  int height = this->Table->horizontalHeader()->sizeHint().height() + 2 * this->Table->frameWidth() +
    this->Table->horizontalScrollBar()->sizeHint().height();
  for (int row = 0; row < std::min(this->Table->rowCount(), 8); ++row)
  {
    height += this->Table->rowHeight(row);
  }
  this->Table->setFixedHeight(height + 2);
}
