// A panel widget for a repeatable string property shown as a table: one row per entry of
// PerRow elements (a column holds one or more of them) under column headers with tool
// tips, with an Add and a Remove button
// (Mark Lights' area lights, the lights' schedule). Subclasses fill the cells, check what is
// typed and make a new entry.
#ifndef pqRadiosityTableWidget_h
#define pqRadiosityTableWidget_h

#include "pqRadiosityRowsWidget.h"

#include <vector>

class QTableWidget;

class pqRadiosityTableWidget : public pqRadiosityRowsWidget
{
  Q_OBJECT
  typedef pqRadiosityRowsWidget Superclass;

public:
  struct Design
  {
    QString Title;          ///< the line above the table
    QString TableName;      ///< the table's object name (tests find it by it)
    QStringList Headers;    ///< one per column
    QStringList Tips;       ///< one per column
    QString AddText, AddName; ///< the Add button's text and object name
    QString RemoveName;     ///< the Remove button's object name
    /// Where each column's elements start in an entry, then the entry's size (PerRow).
    std::vector<int> Starts;
  };
  pqRadiosityTableWidget(vtkSMProxy* proxy, const Design& design, QWidget* parent = nullptr);

protected:
  void rowsSet() override { this->fill(); }
  /// The table from Rows: a row per entry, each cell by fillCell, guarded by Filling.
  void fill();
  /// Cell (row, column) from the entry's elements.
  virtual void fillCell(int row, int column) = 0;
  /// A new entry's elements, for Add (none: Add does nothing).
  virtual QStringList newRow() const = 0;
  /// A typed cell into Rows (or put back).
  virtual void cellEdited(int row, int column) = 0;
  /// The table as tall as its rows (up to 8), with room for a horizontal scroll bar.
  void fitHeight();
  /// Where cell (row, column)'s elements start in Rows, and how many it holds.
  int at(int row, int column) const { return row * this->PerRow + this->Starts[column]; }
  int count(int column) const { return this->Starts[column + 1] - this->Starts[column]; }
  /// Every entry's first element (its name).
  QStringList names() const;
  /// What was typed into cell (row, column) as its elements: the whole text for a `text`
  /// column, else the words between commas, semicolons and spaces.
  QStringList typed(int row, int column, bool text) const;
  /// Whether `parts` fill the column and are finite numbers of at least `low`.
  bool numbers(const QStringList& parts, int column, double low) const;
  /// Whether three numbers are a direction (not all zero).
  static bool direction(const QStringList& parts);
  /// `parts` into Rows where `usable` (rowsChanged said), else the cell shows again what it held.
  void takeOrPutBack(int row, int column, const QStringList& parts, bool usable);
  /// Cell (row, column)'s elements, as Rows holds them.
  QStringList cell(int row, int column) const { return this->Rows.mid(this->at(row, column), this->count(column)); }

  QTableWidget* Table;
  const std::vector<int> Starts;
  const int PerRow;
  bool Filling = false;

private Q_SLOTS:
  void addRow();
  /// The selected entries, else the last one.
  void removeRows();
};

#endif
