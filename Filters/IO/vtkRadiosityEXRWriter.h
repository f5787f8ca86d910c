/**
 * @class   vtkRadiosityEXRWriter
 * @brief   ray-casts a view of a radiosity solution and writes it as OpenEXR (HDR)
 *
 * Display colors are clamped to 8 bits; this writer keeps the linear radiosity. Each
 * pixel shows the point array ArrayName (3 components, default `Radiosity`) interpolated
 * over the polygon hit by the pixel's centre ray (Embree), from a pinhole camera with
 * VTK's conventions (position, focal point, view up, vertical view angle in degrees).
 * The stored value is exitance, the same units as the array.
 *
 * With LightLayers on, the file also holds one layer per light: the solver's
 * `Radiosity_<light>` point array (that light's unit-emission solution) as channels
 * `<light>.R`, `.G`, `.B` (a `.` in a name becomes `_`), next to ArrayName as plain R, G, B
 * where the input has it; all as 32-bit floats, so a compositor can relight the picture.
 *
 * @sa vtkRadiosityRelight
 */
#ifndef vtkRadiosityEXRWriter_h
#define vtkRadiosityEXRWriter_h

#include "vtkRadiosityIOModule.h" // for export macro
#include "vtkWriter.h"

#include <string> // for layer names
#include <vector> // for the pixel buffer

class vtkFloatArray;
class vtkPolyData;
namespace radiosity
{
struct Vec3;
struct PinholeCamera;
}

class VTKRADIOSITYIO_EXPORT vtkRadiosityEXRWriter : public vtkWriter
{
public:
  static vtkRadiosityEXRWriter* New();
  vtkTypeMacro(vtkRadiosityEXRWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  vtkSetStringMacro(ArrayName);
  vtkGetStringMacro(ArrayName);

  ///@{
  /// Camera, as vtkCamera defines it.
  vtkSetVector3Macro(CameraPosition, double);
  vtkGetVector3Macro(CameraPosition, double);
  vtkSetVector3Macro(FocalPoint, double);
  vtkGetVector3Macro(FocalPoint, double);
  vtkSetVector3Macro(ViewUp, double);
  vtkGetVector3Macro(ViewUp, double);
  vtkSetClampMacro(ViewAngle, double, 1e-3, 179.0);
  vtkGetMacro(ViewAngle, double);
  /// Width and height in pixels, each in [GetSizeMinValue(), GetSizeMaxValue()] (the side
  /// the image core accepts); writing with another size is an error that names it.
  vtkSetVector2Macro(Size, int);
  vtkGetVector2Macro(Size, int);
  static int GetSizeMinValue() { return 1; }
  static int GetSizeMaxValue();
  ///@}

  ///@{
  /// Also write one layer per light (see above). Default off: ArrayName alone, half float.
  vtkSetMacro(LightLayers, bool);
  vtkGetMacro(LightLayers, bool);
  vtkBooleanMacro(LightLayers, bool);
  ///@}

  /**
   * Ray-casts the current input into `rgb` (Size[0] * Size[1] tuples of 3 components, row
   * 0 at the top) without writing a file; misses are 0. Returns false with an error on bad
   * input. Used to compare solutions pixel by pixel.
   */
  bool RenderImage(vtkFloatArray* rgb);

  /**
   * Reads back one layer of an OpenEXR file (`layer` a light's name as written, or empty
   * for the plain R, G, B) into `rgb` (width * height tuples of 3, row 0 at the top) and
   * its size into `size`. Returns false with an error naming the file and layer.
   */
  static bool ReadLayer(const char* fileName, const char* layer, vtkFloatArray* rgb, int size[2]);

  /**
   * How many ray scenes this writer has built. Scenes are kept for the process
   * (vtkRadiosityPreparedScenes) and reused while the input's points and polygons are
   * unchanged: an animation's frames build one, and the solver's output builds none where
   * the solver's preparation is still kept.
   */
  int GetRaySceneBuilds() const;

  /**
   * Writes the file, as vtkWriter does, but returns 0 with an error where a filter upstream
   * failed: the update stops there and this writer does not run (vtkWriter would return 1
   * with no file written); a second Write of the same failed pipeline reaches the writer,
   * which finds its input marked as failed and says so.
   */
  int Write() override;

protected:
  vtkRadiosityEXRWriter();
  ~vtkRadiosityEXRWriter() override;
  void WriteData() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

private:
  /// The layers to write, rendered with one ray per pixel; false with an error.
  bool Render(std::vector<std::string>& names, std::vector<std::vector<float>>& images);
  /// The point arrays to draw (ArrayName, and with LightLayers one per light) with their
  /// layer names; "" or why there are none.
  std::string CollectLayers(
    vtkPolyData* input, std::vector<std::string>& names, std::vector<std::vector<radiosity::Vec3>>& layers) const;
  radiosity::PinholeCamera Camera() const;
  vtkRadiosityEXRWriter(const vtkRadiosityEXRWriter&) = delete;
  void operator=(const vtkRadiosityEXRWriter&) = delete;

  char* FileName = nullptr;
  char* ArrayName = nullptr;
  double CameraPosition[3] = { 0, 0, 1 };
  double FocalPoint[3] = { 0, 0, 0 };
  double ViewUp[3] = { 0, 1, 0 };
  double ViewAngle = 30;
  int Size[2] = { 640, 480 };
  bool LightLayers = false;
  int RaySceneBuilds = 0;
};

#endif
