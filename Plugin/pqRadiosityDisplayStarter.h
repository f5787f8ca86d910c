// The pictures a new user should see first, set when ParaView shows the filters' outputs.
#ifndef pqRadiosityDisplayStarter_h
#define pqRadiosityDisplayStarter_h

#include <QObject>

class pqDataRepresentation;
class pqRepresentation;

/**
 * Display defaults for this plugin's outputs in the GUI, applied once, right after
 * ParaView has shown an output with its own defaults (the user can change them after):
 * - Radiosity Relight: its DisplayColors as they are (no color map, no shading on top);
 * - Light Tagged Radiosity, colored by a Radiosity_* or Direct_* array: an HDR color
 *   map (Inferno) and the unit in the legend;
 * - its Convergence output (a line chart by the XML's View hint): unshot energy per shot
 *   on a log axis, one line per light.
 */
class pqRadiosityDisplayStarter : public QObject
{
  Q_OBJECT

public:
  explicit pqRadiosityDisplayStarter(QObject* parent = nullptr);
  void startup();
  void shutdown() {}

private:
  void onRepresentationAdded(pqRepresentation* representation);
  void Configure(pqDataRepresentation* representation);
  static void ShowRelitColors(pqDataRepresentation* representation);
  static void ShowRelitSurface(pqDataRepresentation* representation);
  static void ShowConvergence(pqDataRepresentation* representation);
  static void StyleRadiosityColorMap(pqDataRepresentation* representation);
  static void LeaveRelitToColor(pqDataRepresentation* representation);
};

#endif
