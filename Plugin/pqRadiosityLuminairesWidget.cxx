#include "pqRadiosityLuminairesWidget.h"
#include "pqRadiosityLampPlacement.h"

#include "pqActiveObjects.h"
#include "pqFileDialog.h"

#include "vtkRadiosityLightMarker.h"

#include <QComboBox>
#include <QPushButton>
#include <QRegularExpression>
#include <QSignalBlocker>
#include <QTableWidget>

#include <cmath>

namespace
{
enum Column
{
  Name = 0,
  Kind,
  Parameters,
  File,
  Position,
  Aim,
  Rotation,
  Color
};
/// The kinds of light, as the core's registry lists them.
QStringList Kinds()
{
  QStringList kinds;
  for (int i = 0; i < vtkRadiosityLightMarker::GetNumberOfLightKinds(); ++i)
  {
    kinds << vtkRadiosityLightMarker::GetLightKindName(i);
  }
  return kinds;
}
}

pqRadiosityLuminairesWidget::pqRadiosityLuminairesWidget(vtkSMProxy* proxy, vtkSMProperty* property, QWidget* parent)
  : Superclass(proxy,
      { "Luminaires (lights at points; positions in the scene's units):", "LuminairesTable",
        { "Name", "Kind", "Parameters", "File", "Position x, y, z", "Aim x, y, z", "Rotation (°)", "Color r, g, b" },
        { "The light's name: letters, digits and _", "goniometric (a photometric file), point, spot or lambertian",
          "name=value; ...: file=<IES or EULUMDAT>, lumens=<the file's if left out>; a spot's cone=, falloff= (degrees)",
          "Pick the IES LM-63 or EULUMDAT file (sets file=...)", "Where the luminaire is",
          "The direction it shines (its nadir: straight down for a downlight)",
          "Its turn about the aim: where its C0 plane points", "Its default color when relit" },
        "Add Luminaire", "AddLuminaire", "RemoveLuminaires",
        // the elements of a luminaire: name, kind, parameters, (the File button: none),
        // position, aim, rotation, color
        { 0, 1, 2, 3, 3, 6, 9, 10, 13 } },
      parent)
{
  this->linkRows(property);
  this->fill();
}

void pqRadiosityLuminairesWidget::fillCell(int row, int column)
{
  if (column == Kind)
  {
    auto* kind = new QComboBox(this->Table);
    const QStringList kinds = Kinds();
    kind->addItems(kinds);
    kind->setCurrentIndex(std::max(0, kinds.indexOf(this->cell(row, column).value(0))));
    QObject::connect(kind, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this, kind](int) {
      for (int r = 0; r < this->Table->rowCount(); ++r)
      {
        if (this->Table->cellWidget(r, Kind) == kind)
        {
          this->Rows[this->at(r, Kind)] = kind->currentText();
          Q_EMIT this->rowsChanged();
        }
      }
    });
    this->Table->setCellWidget(row, column, kind);
    return;
  }
  if (column == File)
  {
    auto* pick = new QPushButton("File…", this->Table);
    pick->setObjectName("PickPhotometricFile");
    QObject::connect(pick, &QPushButton::clicked, this, [this, pick]() {
      for (int r = 0; r < this->Table->rowCount(); ++r)
      {
        if (this->Table->cellWidget(r, File) == pick)
        {
          this->pickFile(r);
        }
      }
    });
    this->Table->setCellWidget(row, column, pick);
    return;
  }
  this->Table->setItem(row, column, new QTableWidgetItem(this->cell(row, column).join(", ")));
}

void pqRadiosityLuminairesWidget::pickFile(int row)
{
  pqFileDialog dialog(pqActiveObjects::instance().activeServer(), this, "Photometric file", QString(),
    "Photometric files (*.ies *.IES *.ldt *.LDT);;All files (*)");
  dialog.setFileMode(pqFileDialog::ExistingFile);
  if (dialog.exec() != QDialog::Accepted || dialog.getSelectedFiles().isEmpty())
  {
    return;
  }
  // The file replaces a file=... among the parameters, the rest stays.
  QStringList kept;
  for (const QString& pair : this->Rows[this->at(row, Parameters)].split(';', Qt::SkipEmptyParts))
  {
    if (!pair.trimmed().startsWith("file"))
    {
      kept << pair.trimmed();
    }
  }
  kept.prepend("file=" + dialog.getSelectedFiles().first());
  this->Rows[this->at(row, Parameters)] = kept.join("; ");
  this->Rows[this->at(row, Kind)] = "goniometric";
  this->fill();
  Q_EMIT this->rowsChanged();
}

void pqRadiosityLuminairesWidget::cellEdited(int row, int column)
{
  if (!this->Table->item(row, column) || column == Kind || column == File)
  {
    return;
  }
  const QStringList parts = this->typed(row, column, column == Name || column == Parameters);
  const bool usable = column == Name ? !parts[0].isEmpty()
    : column == Parameters           ? true
                                     : this->numbers(parts, column, column == Color ? 0 : -HUGE_VAL) &&
      (column != Aim || direction(parts));
  this->takeOrPutBack(row, column, parts, usable);
}

QStringList pqRadiosityLuminairesWidget::newRow() const
{
  const pqRadiosityLampPlacement::NewLamp lamp = pqRadiosityLampPlacement::Place(this->proxy(), "Luminaire", this->names());
  return QStringList{ lamp.Name, "goniometric", "" } << lamp.Centre << lamp.Facing << "0" << "1" << "1" << "1";
}
