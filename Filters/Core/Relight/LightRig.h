// The lights' settings and what decides them: defaults, settings by name, a schedule of
// keyframes over time, settings by index. One place for the precedence, so the relight
// filter, a renderer that relights on the GPU and Python give the same colors.
#ifndef RadiosityCore_LightRig_h
#define RadiosityCore_LightRig_h

#include "Base/Vec3.h"

#include <map>
#include <string>
#include <vector>

namespace radiosity
{

/// A light's color, intensity and on/off; a part without its Has flag leaves what lies
/// below it (a default, or a setting of lower precedence) as it is.
struct LightSetting
{
  bool HasColor = false;
  Vec3 Color{ 1, 1, 1 };
  bool HasIntensity = false;
  double Intensity = 1;
  bool HasEnabled = false;
  bool Enabled = true;
  void ApplyTo(LightSetting& effective) const;
  /// Its contribution weight per channel: color x intensity, or zero when off.
  Vec3 Weight() const { return Enabled ? Color * Intensity : Vec3(); }
};

/// Why a light's values cannot be used (empty when they can): light is never negative,
/// and NaN would silently blank the picture.
std::string InvalidLightValues(double intensity, const Vec3& color);

/// A light's setting as the row ParaView's LightSettings and LightSettingsInfo hold: name,
/// r, g, b, intensity, enabled ("1"/"0"), numbers to 9 significant digits. The filter's and
/// the mapper's read-back both write it here, so a new column is added once.
std::vector<std::string> SettingRow(const std::string& name, const LightSetting& setting);

/// A setting as a row a user gives (LightSettings): as SettingRow, but a color or intensity
/// the setting leaves unset is written 'nan' ("keep the default").
std::vector<std::string> SettingInputRow(const std::string& name, const LightSetting& setting);

/// One row of a LightSettings list, read back.
struct NamedSetting
{
  std::string Name;
  LightSetting Setting;
};

/// What a cell of a light's row holds: ParaView's element type for it (text; a real
/// number, alone or one of a color's three parts; an integer used as on/off), and the
/// editor the panel gives it.
enum class RowCell
{
  Text,
  Color,
  Number,
  Flag
};
/// One cell of a light's row: its name, what it holds, the panel's column it is shown in
/// (cells with one heading are one part of the setting, set together or not at all), the
/// range a Number takes there, and how it is read from and written into a LightSetting
/// (none for the name).
struct SettingColumn
{
  const char* Name;
  RowCell Kind;
  const char* Heading;
  double Low, High;
  double (*Get)(const LightSetting&);
  void (*Set)(LightSetting&, double);
  bool (*Has)(const LightSetting&);
};
/// The columns of one light's row, in order: the one declaration of the row. Its writing
/// (SettingRow, SettingInputRow) and reading (ParseSettingRows) go through it, ParaView's
/// LightSettings property takes its element count, types and documented columns from it
/// (the plugin's LightRig.xml is filled in at build time) and the panel its columns and
/// editors. A new per-light setting: its LightSetting field (with ApplyTo and what it
/// does in Weight) and its row here.
inline constexpr SettingColumn kSettingRowColumns[] = {
  { "name", RowCell::Text, "Light", 0, 0, nullptr, nullptr, nullptr },
  { "red", RowCell::Color, "Color", 0, 0, [](const LightSetting& s) { return s.Color.x; },
    [](LightSetting& s, double v) { s.Color.x = v, s.HasColor = true; }, [](const LightSetting& s) { return s.HasColor; } },
  { "green", RowCell::Color, "Color", 0, 0, [](const LightSetting& s) { return s.Color.y; },
    [](LightSetting& s, double v) { s.Color.y = v, s.HasColor = true; }, [](const LightSetting& s) { return s.HasColor; } },
  { "blue", RowCell::Color, "Color", 0, 0, [](const LightSetting& s) { return s.Color.z; },
    [](LightSetting& s, double v) { s.Color.z = v, s.HasColor = true; }, [](const LightSetting& s) { return s.HasColor; } },
  { "intensity", RowCell::Number, "Intensity", 0, 1e9, [](const LightSetting& s) { return s.Intensity; },
    [](LightSetting& s, double v) { s.Intensity = v, s.HasIntensity = true; },
    [](const LightSetting& s) { return s.HasIntensity; } },
  { "enabled", RowCell::Flag, "On", 0, 1, [](const LightSetting& s) { return s.Enabled ? 1.0 : 0.0; },
    [](LightSetting& s, double v) { s.Enabled = v != 0, s.HasEnabled = true; },
    [](const LightSetting& s) { return s.HasEnabled; } },
};
constexpr int kSettingRowCells = static_cast<int>(sizeof(kSettingRowColumns) / sizeof(kSettingRowColumns[0]));

/// The rows of a flat LightSettings list (kSettingRowCells strings a light, as SettingRow
/// and SettingInputRow write them): a color or intensity that is not a finite number ('nan')
/// is left unset; `enabled` as ParseOnOff reads it. A row with an empty name or an
/// unreadable `enabled`, and a trailing part-row, are skipped.
std::vector<NamedSetting> ParseSettingRows(const std::vector<std::string>& flat);

/// On or off as text: true/false, on/off, yes/no in any case, or a number (not 0: on, as
/// an integer property takes it). False if it is none of these.
bool ParseOnOff(const std::string& text, bool& on);

/// A keyframe of the schedule: the light by name, or by index written as a number.
struct LightKeyframe
{
  double Time = 0;
  std::string Light;
  Vec3 Color{ 1, 1, 1 };
  double Intensity = 1;
  bool Enabled = true;
};

/// Parses one schedule row (time, light, r, g, b, intensity[, enabled]) whose cells are
/// already split; `enabled` as true/false, on/off, yes/no or 1/0. False if malformed.
bool ParseKeyframe(const std::vector<std::string>& cells, LightKeyframe& key);

/// One row of a light scene (Relight/LightScenes.h): the lights it sets (a name or a shell
/// pattern, `*` and `?`, case ignored) and what it sets of them: its dimming as the
/// intensity (a fraction of the light's own strength), a color where given, on or off.
struct LightSceneRow
{
  std::string Scene;
  std::string Lights;
  LightSetting Setting;
};

struct LightRig
{
  std::map<int, LightSetting> ByIndex;
  std::map<std::string, LightSetting> ByName;
  std::vector<LightKeyframe> Schedule; ///< keyframes given one by one
  std::vector<LightKeyframe> FileSchedule; ///< keyframes read from a file
  /// Light scenes (from a file) and the one in effect (empty: none). A keyframe whose light
  /// is "scene:<name>" gives every light that scene sets its setting at that time, so the
  /// schedule switches and blends scenes.
  std::vector<LightSceneRow> Scenes;
  std::string ActiveScene;

  ///@{
  /// Settings by index, one part at a time.
  void SetColor(int light, const Vec3& color);
  void SetIntensity(int light, double intensity);
  void SetEnabled(int light, bool enabled);
  ///@}

  /// A whole setting by name; a NaN color component or intensity keeps that part at its
  /// default (a panel that changed only the intensity must not replace the color).
  void SetByName(const std::string& name, const Vec3& color, double intensity, bool enabled);

  /// The schedule's setting for light `name` (index `index`, default setting `base`) at
  /// `time`: color and intensity interpolated linearly between keyframes, on/off held from
  /// the one before. False if no keyframe names the light (or a scene that sets it).
  bool Scheduled(const std::string& name, int index, double time, const LightSetting& base, LightSetting& out) const;

  /// Every keyframe time, sorted, each once.
  std::vector<double> KeyframeTimes() const;

  /// The settings in effect for lights `names` with `defaults` (their default colors),
  /// at `time`: defaults, then the active light scene, then by name, then the schedule,
  /// then by index. Returns an empty
  /// string, or the error for a light switched on with a negative, infinite or NaN value.
  /// `warnings` gets settings that name no light.
  std::string Resolve(const std::vector<std::string>& names, const std::vector<Vec3>& defaults, double time,
    std::vector<LightSetting>& effective, std::vector<std::string>& warnings) const;
};

/// The 3k weights (color x intensity, zero for lights off) of resolved settings; with an
/// indirect scale other than 1, 6k: s times the totals, then (1 - s) times the direct
/// parts, for B = s B_total + (1 - s) B_direct.
std::vector<double> LightWeights(const std::vector<LightSetting>& effective, double indirectScale);

/// A reader's memory of the light-setting warnings it said (LightRig::Resolve's): an
/// animation resolves the settings every frame, and the same words each frame would bury
/// the rest of the log.
class SaidOnce
{
public:
  /// Of `warnings`, those not among the ones passed last time; remembers `warnings`.
  std::vector<std::string> New(const std::vector<std::string>& warnings);

private:
  std::vector<std::string> Said;
};

} // namespace radiosity

#endif
