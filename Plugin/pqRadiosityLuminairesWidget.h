// ParaView panel for Mark Lights' luminaires: one row per luminaire under column headers
// (name, kind, its parameters, a File button that picks an IES or EULUMDAT file, position,
// aim, rotation, color), Add and Remove buttons.
#ifndef pqRadiosityLuminairesWidget_h
#define pqRadiosityLuminairesWidget_h

#include "pqRadiosityTableWidget.h"

class pqRadiosityLuminairesWidget : public pqRadiosityTableWidget
{
  Q_OBJECT
  typedef pqRadiosityTableWidget Superclass;

public:
  // Rows: 13 per luminaire (name, kind, parameters, position x y z, aim x y z, rotation,
  // color r g b).
  pqRadiosityLuminairesWidget(vtkSMProxy* proxy, vtkSMProperty* property, QWidget* parent = nullptr);

protected:
  void fillCell(int row, int column) override;
  /// A new luminaire: at the top of the input's box, aimed down, its file still to pick.
  QStringList newRow() const override;
  /// A typed cell into the rows; a cell that does not read as its numbers is put back.
  void cellEdited(int row, int column) override;

private:
  /// The server's file dialog; the chosen file becomes the row's file=... parameter.
  void pickFile(int row);
};

#endif
