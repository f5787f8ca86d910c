// A panel widget for a repeatable string property shown as a table: one row per entry of
// PerRow elements under column headers with tool tips, with an Add and a Remove button
// (Mark Lights' area lights, the lights' schedule). Subclasses fill the cells, check what is
// typed and make a new entry.
#ifndef pqRadiosityTableWidget_h
#define pqRadiosityTableWidget_h

#include "pqRadiosityRowsWidget.h"

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
    int PerRow = 1;         ///< property elements per entry
  };
  pqRadiosityTableWidget(vtkSMProxy* proxy, const Design& design, QWidget* parent = nullptr);

protected:
  void rowsSet() override { this->fill(); }
  /// The table from Rows: a row per entry, each cell by fillCell, guarded by Filling.
  void fill();
  /// Cell (row, column) from the entry's elements.
  virtual void fillCell(int row, int column) = 0;
  /// A new entry's elements, for Add.
  virtual QStringList newRow() const = 0;
  /// A typed cell into Rows (or put back).
  virtual void cellEdited(int row, int column) = 0;
  /// The table as tall as its rows (up to 8), with room for a horizontal scroll bar.
  void fitHeight();

  QTableWidget* Table;
  const int PerRow;
  bool Filling = false;

private Q_SLOTS:
  void addRow();
  /// The selected entries, else the last one.
  void removeRows();
};

#endif
