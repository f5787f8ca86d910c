/**
 * @class   vtkRadiosityLights
 * @brief   the lights' settings: color, intensity and on/off by index or by name, and a schedule
 *
 * One object holds what a user sets about the lights, and the relight filter, the GPU mapper
 * and ParaView's Relit Surface read it: a new light setting is added here and to the core's
 * radiosity::LightRig, which resolves it (a new column of the per-light row also where the
 * row is read and written: docs/design.md lists them). Share one object between a filter
 * and a mapper (SetLights) and both follow the same changes.
 *
 * Precedence, as the core resolves it: each light's default (from the solver's output),
 * then settings by name, then the schedule at the reader's time, then settings by index.
 * A NaN color component or intensity in a setting by name keeps that part at its default.
 * Every change modifies this object; readers take its modification time as their own.
 *
 * @sa vtkRadiosityRelight vtkRadiosityRelightMapper
 */
#ifndef vtkRadiosityLights_h
#define vtkRadiosityLights_h

#include "vtkObject.h"
#include "vtkRadiosityFiltersModule.h" // for export macro

#include <memory> // for the rig
#include <string> // for errors
#include <vector> // for names and settings

namespace radiosity
{
struct LightRig;
struct LightSetting;
struct Vec3;
}
class vtkPolyData;

class VTKRADIOSITYFILTERS_EXPORT vtkRadiosityLights : public vtkObject
{
public:
  static vtkRadiosityLights* New();
  vtkTypeMacro(vtkRadiosityLights, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Strings a row of LightSettings holds (name, r, g, b, intensity, enabled): the
  /// plugin's LightRig.xml sends rows of this many (checked by Python.TestNames).
  static int GetSettingRowCells();
  /// Column `i` of that row: its name, and the VTK type of what it holds (VTK_STRING,
  /// VTK_DOUBLE, VTK_INT for on/off); null and 0 past the row.
  static const char* GetSettingRowColumnName(int i);
  static int GetSettingRowColumnType(int i);
  /// How ParaView's lights panel shows cell `i`: the heading of its column (cells with one
  /// heading are one part, shown together: a color's three), its editor (ColumnEditor) and
  /// the range a number takes there.
  enum ColumnEditor
  {
    NAME_CELL,
    COLOR_CELL,
    NUMBER_CELL,
    FLAG_CELL
  };
  static const char* GetSettingRowColumnHeading(int i);
  static int GetSettingRowColumnEditor(int i);
  static double GetSettingRowColumnLow(int i);
  static double GetSettingRowColumnHigh(int i);

  ///@{
  /// Per-light settings by index (0..k-1, in LightNames order).
  void SetLightColor(int light, double r, double g, double b);
  void SetLightIntensity(int light, double intensity);
  void SetLightEnabled(int light, bool enabled);
  ///@}

  ///@{
  /// Per-light settings by name, all at once (ParaView's repeatable property).
  void SetLightSetting(const char* name, double r, double g, double b, double intensity, int enabled);
  void ClearLightSettings();
  /// How many lights have a setting by name (the rest keep their defaults).
  int GetNumberOfLightSettings() const;
  ///@}

  /// Forget every setting made by index or by name (the schedule stays).
  void ResetLights();

  ///@{
  /// Keyframes (time, light by name or index, r, g, b, intensity, enabled): color and
  /// intensity interpolated linearly between them, `enabled` held from the one before.
  void AddScheduleEntry(double time, const char* light, double r, double g, double b, double intensity, int enabled);
  /// The same with `enabled` as text, as a schedule file's cell and ParaView's property give
  /// it (radiosity::ParseOnOff: true/false, on/off, yes/no or a number); anything else makes
  /// the schedule an error, named when the lights are resolved, until ClearSchedule.
  void AddScheduleRow(double time, const char* light, double r, double g, double b, double intensity, const char* enabled);
  void ClearSchedule();
  int GetNumberOfScheduleEntries() const;
  ///@}

  ///@{
  /// A CSV file of keyframes, added to the entries above: names quoted where they hold
  /// commas, an optional header whose first column is "time", the columns of
  /// AddScheduleEntry with `enabled` optional (true/false, on/off, yes/no or 1/0). Read
  /// by ReadScheduleFile, again whenever the file changes.
  vtkSetStringMacro(ScheduleFileName);
  vtkGetStringMacro(ScheduleFileName);
  ///@}

  ///@{
  /// Light scenes: a file of rows "scene, lights, dimming %, r, g, b, on" (lights a name
  /// or a pattern, * and ?; r, g, b empty to keep the lights' colors; '#' comments), and
  /// the scene in effect (empty: none). The scene lies under the settings by name; a
  /// schedule keyframe whose light is "scene:<name>" gives its lights that scene's
  /// settings then, so scenes switch and blend over time. Read again whenever it changes.
  vtkSetStringMacro(LightScenesFileName);
  vtkGetStringMacro(LightScenesFileName);
  void SetLightScene(const char* scene);
  const char* GetLightScene() const;
  /// The scenes the file defines, after a read (ReadScheduleFile reads it too).
  int GetNumberOfLightScenes() const;
  const char* GetLightSceneName(int i) const;
  ///@}

  /// Reads the schedule file (and the light-scenes file) if it was not read as it is now
  /// (cheap otherwise); false with `error` set if it cannot be read or a row is malformed,
  /// its keyframes then dropped. Every reader of the settings calls this before resolving
  /// them.
  bool ReadScheduleFile(std::string& error);

#ifndef __VTK_WRAP__
  /// The settings for the core to resolve (C++ only). A caller that changes them calls
  /// Modified().
  radiosity::LightRig& Rig() { return *this->Settings; }
  const radiosity::LightRig& Rig() const { return *this->Settings; }

  /// The settings in effect at `time` for the lights `names` whose defaults are
  /// `defaults`, the schedule file read first: what the relight filter, the GPU mapper and
  /// Relit Surface each resolve (C++ only). An error (a bad value, an unreadable schedule)
  /// or ""; `warnings` name lights the data does not have.
  std::string Resolve(const std::vector<std::string>& names, const std::vector<radiosity::Vec3>& defaults,
    double time, std::vector<radiosity::LightSetting>& effective, std::vector<std::string>& warnings);

  /// A light as the ParaView panel shows it, cell by cell of its row: the plugin reads and
  /// writes the rows through these (it sees this layer only) and takes its columns from
  /// the row's declaration above, so a new column is neither parsed nor shown by hand.
  struct ShownLight
  {
    std::string Name;
    std::vector<double> Cells;    ///< the value in effect of each cell (the name's: 0)
    std::vector<char> CellEdited; ///< per cell: a row of the edited ones sets its part
    bool Edited = false;          ///< a row of the edited ones names it
  };
  /// The lights of `inEffect` (the filter's read-back rows, flat) with the rows `edited`
  /// (the property's, flat) applied, in the read-back's order.
  static std::vector<ShownLight> ShownLights(
    const std::vector<std::string>& inEffect, const std::vector<std::string>& edited);
  /// The property's row for an edited light: the parts it edited, the others 'nan' (kept).
  static std::vector<std::string> EditedRow(const ShownLight& light);
  /// Reads a schedule row as the schedule file does: false where it does not read; the
  /// light's name and its on/off otherwise.
  static bool ReadScheduleRow(const std::vector<std::string>& cells, std::string& light, bool& enabled);

#endif

protected:
  vtkRadiosityLights();
  ~vtkRadiosityLights() override;

private:
  vtkRadiosityLights(const vtkRadiosityLights&) = delete;
  void operator=(const vtkRadiosityLights&) = delete;

  std::unique_ptr<radiosity::LightRig> Settings;
  char* ScheduleFileName = nullptr;
  char* LightScenesFileName = nullptr;
  std::string ScenesFile;    ///< the light-scenes file as last read
  long long ScenesStamp = 0; ///< its last write time then
  std::vector<std::string> SceneNames;
  /// Reads the light-scenes file if it changed; false with `error` where it cannot.
  bool ReadScenesFile(std::string& error);
  std::string EntryError;    ///< an entry given whose `enabled` does not read
  std::string ReadFile;      ///< the schedule file as last read
  long long ReadStamp = 0;   ///< its last write time then: a newer one re-reads it
};

#endif
