#include "vtkRadiosityRelightMapper.h"

#include "Relight/LightRig.h"
#include "vtkRadiosityLights.h"
#include "vtkRadiosityCombine.h"

#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkStringArray.h"
#include "vtkTextureObject.h"
#include "vtkUnsignedCharArray.h"
#include "Relight/Relight.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkRadiosityRelightMapper);

struct vtkRadiosityRelightMapper::Internals
{
  vtkSmartPointer<vtkRadiosityLights> Lights = vtkSmartPointer<vtkRadiosityLights>::New();
  double Time = 0;
  double Exposure = 0;
  double Metered = 1;                 ///< the metered exposure, for the weights and data below
  std::vector<float> MeteredWeights;  ///< empty where metered at the lights' defaults
  vtkMTimeType MeteredFor = 0;
  vtkRadiosityRelitInput Input;         ///< the lights and solutions of the data uploaded
  std::vector<std::string> Names;       ///< its lights, where it has a problem none
  std::vector<radiosity::Vec3> Defaults; ///< their default colors
  vtkNew<vtkOpenGLBufferObject> Buffer;
  vtkNew<vtkTextureObject> Texture;
  vtkPolyData* UploadedData = nullptr;
  vtkMTimeType UploadedTime = 0;
  int Uploads = 0;
  int ShaderLights = -1; ///< the k the current shader was built for
  std::string Problem;  ///< with the data uploaded (cleared by the next upload)
  std::string Reported; ///< the problem last reported, so each is said once
  std::string SettingsProblem; ///< with the lights' settings now (cleared when they resolve)
  radiosity::SaidOnce ReportedSettings; ///< the light settings' warnings, each said once
  bool UseGPU = true;
  bool OnCPU = false;       ///< this data is relit on the CPU (asked for, or fallen back to)
  std::string WhyCPU;       ///< the reason, said once
  std::string ReportedCPU;
  vtkSmartPointer<vtkPolyData> Colored; ///< the input with CPU-summed display colors
  std::vector<float> ColoredWeights;   ///< the weights and exposure it was made with
  double ColoredExposure = -1;
  vtkMTimeType ColoredFor = 0;
};

namespace
{

/// GLSL added before the vertex shader's main(): the solutions and the light uniforms.
std::string VertexDeclarations(int k)
{
  return "uniform samplerBuffer relightSolutions;\nuniform vec3 relightWeights[" + std::to_string(std::max(k, 1)) +
    "];\nuniform float relightExposure;\nout vec3 relightColor;\n";
}

/// GLSL added at the end of the vertex shader's main(): sum, exposure, clamp, sRGB.
std::string VertexColor(int k)
{
  return "  vec3 relightSum = vec3(0.0);\n"
         "  for (int i = 0; i < " + std::to_string(k) + "; ++i)\n"
         "  {\n"
         "    int t = 3 * (gl_VertexID * " + std::to_string(k) + " + i);\n"
         "    relightSum += relightWeights[i] * vec3(texelFetch(relightSolutions, t).r,\n"
         "      texelFetch(relightSolutions, t + 1).r, texelFetch(relightSolutions, t + 2).r);\n"
         "  }\n"
         "  vec3 relightValue = clamp(relightSum * relightExposure, 0.0, 1.0);\n"
         "  relightColor = mix(relightValue * 12.92, 1.055 * pow(relightValue, vec3(1.0 / 2.4)) - 0.055,\n"
         "    step(0.0031308, relightValue));\n";
}

/// Inserts `declarations` before main() and `body` before main()'s closing brace.
void Extend(vtkShader* shader, const std::string& declarations, const std::string& body)
{
  std::string source = shader->GetSource();
  const size_t main = source.find("void main()");
  const size_t end = source.rfind('}');
  if (main == std::string::npos || end == std::string::npos || end < main)
  {
    return;
  }
  source.insert(end, body);
  source.insert(main, declarations);
  shader->SetSource(source);
}


} // namespace

vtkRadiosityRelightMapper::vtkRadiosityRelightMapper()
  : Internal(new Internals)
{
  this->ScalarVisibilityOff(); // the color comes from the shader
}

vtkRadiosityRelightMapper::~vtkRadiosityRelightMapper() = default;

vtkRadiosityLights* vtkRadiosityRelightMapper::GetLights()
{
  return this->Internal->Lights;
}

void vtkRadiosityRelightMapper::SetLights(vtkRadiosityLights* lights)
{
  if (lights)
  {
    this->Internal->Lights = lights;
  }
}

void vtkRadiosityRelightMapper::SetTime(double time)
{
  this->Internal->Time = time;
}

double vtkRadiosityRelightMapper::GetTime() const
{
  return this->Internal->Time;
}

void vtkRadiosityRelightMapper::SetExposure(double exposure)
{
  if (!(exposure >= 0 && exposure <= VTK_DOUBLE_MAX))
  {
    // As the relight filter refuses it; the picture keeps the exposure it had.
    vtkErrorMacro(<< "Exposure (" << exposure << ") must be finite and not negative; kept at "
                  << this->Internal->Exposure << ".");
    return;
  }
  this->Internal->Exposure = exposure;
}

double vtkRadiosityRelightMapper::GetExposure() const
{
  return this->Internal->Exposure;
}

int vtkRadiosityRelightMapper::GetNumberOfLights() const
{
  return static_cast<int>(this->Internal->Names.size());
}

int vtkRadiosityRelightMapper::GetUploadCount() const
{
  return this->Internal->Uploads;
}

const char* vtkRadiosityRelightMapper::GetLastProblem() const
{
  const Internals& in = *this->Internal;
  return (in.Problem.empty() ? in.SettingsProblem : in.Problem).c_str();
}

void vtkRadiosityRelightMapper::UploadIfNeeded(vtkRenderer* ren)
{
  Internals& in = *this->Internal;
  vtkPolyData* data = this->CurrentInput;
  if (!data || (data == in.UploadedData && data->GetMTime() <= in.UploadedTime))
  {
    return;
  }
  in.UploadedData = data;
  in.UploadedTime = data->GetMTime();
  // The relight filter's reading of its input: the same lights, defaults and arrays.
  in.Problem = in.Input.ReadLights(data);
  in.Problem = in.Problem.empty() ? in.Input.ReadTables(data) : in.Problem;
  if (in.Problem.empty() && !in.Input.HasPoints())
  {
    in.Problem = "the input has no point arrays 'Radiosity_<light>' (this mapper colors the points; the light-tagged "
                 "solver writes them)";
  }
  size_t item = 0, light = 0;
  if (in.Problem.empty() && in.Input.FindNonFinite(false, item, light))
  {
    // Said once, as a problem of the input, and drawn black: a NaN would blank the shader's
    // sum, and the CPU path's metering would say it at every frame.
    in.Problem = "the solution of light '" + in.Input.GetNames()[light] + "' is not finite at point " +
      std::to_string(item) + "; the input's Radiosity_<light> arrays must hold finite numbers";
  }
  in.Names.clear();
  in.Defaults.clear();
  if (!in.Problem.empty())
  {
    in.OnCPU = false; // drawn black by the GPU path's shader of no lights, whatever drew before
    in.WhyCPU.clear();
    return;
  }
  const size_t k = in.Input.GetNames().size();
  in.Names = in.Input.GetNames();
  in.Defaults = in.Input.GetDefaultColors();
  const size_t points = static_cast<size_t>(data->GetNumberOfPoints());
  GLint most = 0, vectors = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &most);
  glGetIntegerv(GL_MAX_VERTEX_UNIFORM_VECTORS, &vectors);
  constexpr int VtkOwnVectors = 64; // VTK's own vertex uniforms (matrices and the like), with room to spare
  in.WhyCPU = !in.UseGPU ? "asked for (UseGPU off)"
    : static_cast<double>(points) * k * 3 > most
    ? std::to_string(points) + " points x " + std::to_string(k) + " lights need " + std::to_string(points * k * 3) +
      " texels, more than this OpenGL's texture buffers hold (" + std::to_string(most) + ")"
    : static_cast<GLint>(k) > vectors - VtkOwnVectors
    ? std::to_string(k) + " lights need as many uniform vectors, and this OpenGL's vertex shaders have " +
      std::to_string(vectors) + " (less what VTK uses)"
    : std::string();
  in.OnCPU = !in.WhyCPU.empty();
  if (in.OnCPU)
  {
    return; // the solutions stay on the CPU
  }
  // Point-major: the k solutions of a vertex lie together, for one texel run per vertex.
  const std::vector<float> values = in.Input.Interleaved(false);
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  in.Texture->SetContext(window);
  in.Buffer->Upload(values, vtkOpenGLBufferObject::TextureBuffer);
  in.Texture->CreateTextureBuffer(static_cast<unsigned int>(values.size()), 1, VTK_FLOAT, in.Buffer);
  ++in.Uploads;
}

void vtkRadiosityRelightMapper::DescribeLights(vtkPolyData* data, vtkStringArray* names, vtkStringArray* settings)
{
  names->Initialize();
  settings->Initialize();
  if (!data)
  {
    return;
  }
  vtkRadiosityRelitInput input;
  if (!input.ReadLights(data).empty())
  {
    return;
  }
  const std::vector<std::string>& lights = input.GetNames();
  std::vector<radiosity::LightSetting> effective;
  std::vector<std::string> warnings;
  if (!this->Internal->Lights->Resolve(lights, input.GetDefaultColors(), this->Internal->Time, effective, warnings).empty())
  {
    return;
  }
  for (size_t l = 0; l < lights.size(); ++l)
  {
    names->InsertNextValue(lights[l]);
    for (const std::string& item : radiosity::SettingRow(lights[l], effective[l]))
    {
      settings->InsertNextValue(item);
    }
  }
}

void vtkRadiosityRelightMapper::RenderPieceStart(vtkRenderer* ren, vtkActor* act)
{
  Internals& in = *this->Internal;
  this->UploadIfNeeded(ren);
  if (!in.Problem.empty() && in.Problem != in.Reported)
  {
    vtkErrorMacro(<< "Cannot relight: " << in.Problem << ".");
    in.Reported = in.Problem;
  }
  if (in.OnCPU && in.WhyCPU != in.ReportedCPU)
  {
    vtkWarningMacro(<< "Relighting on the CPU: " << in.WhyCPU << "; each light change uploads new colors.");
    in.ReportedCPU = in.WhyCPU;
  }
  // The CPU path draws display colors as VTK's own mapper would; the GPU path draws none.
  const bool scalars = in.OnCPU && in.Problem.empty();
  if (this->ScalarVisibility != (scalars ? 1 : 0))
  {
    this->ScalarVisibility = scalars ? 1 : 0;
    this->ColorMode = VTK_COLOR_MODE_DIRECT_SCALARS;
  }
  if (scalars)
  {
    this->CurrentInput = this->CpuColored();
  }
  this->Superclass::RenderPieceStart(ren, act);
}

std::vector<float> vtkRadiosityRelightMapper::CurrentWeights()
{
  Internals& in = *this->Internal;
  std::vector<radiosity::LightSetting> effective;
  std::vector<std::string> warnings;
  const std::string invalid = in.Lights->Resolve(in.Names, in.Defaults, in.Time, effective, warnings);
  if (!invalid.empty())
  {
    effective.assign(in.Names.size(), radiosity::LightSetting());
    for (radiosity::LightSetting& s : effective)
    {
      s.Enabled = false;
    }
    if (in.SettingsProblem != invalid)
    {
      vtkErrorMacro(<< "Cannot relight: " << invalid << ".");
    }
  }
  in.SettingsProblem = invalid; // a schedule file mended, a setting corrected: drawn again
  for (const std::string& warning : in.ReportedSettings.New(warnings))
  {
    vtkWarningMacro(<< warning); // a light index or name the data does not have
  }
  std::vector<float> weights;
  for (double w : radiosity::LightWeights(effective, 1.0))
  {
    weights.push_back(static_cast<float>(w));
  }
  return weights;
}

vtkPolyData* vtkRadiosityRelightMapper::CpuColored()
{
  Internals& in = *this->Internal;
  vtkPolyData* data = in.UploadedData;
  const std::vector<float> weights = this->CurrentWeights();
  if (in.Colored && in.ColoredFor == data->GetMTime() && in.ColoredWeights == weights &&
    in.ColoredExposure == this->GetExposureInUse())
  {
    return in.Colored;
  }
  const vtkIdType points = data->GetNumberOfPoints();
  vtkNew<vtkFloatArray> linear;
  this->SumOnCpu(weights, linear);
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetName("RelitDisplayColors");
  colors->SetNumberOfComponents(3);
  colors->SetNumberOfTuples(points);
  static const radiosity::DisplayCurve curve;
  curve.Apply(linear->GetPointer(0), 3 * static_cast<size_t>(points), this->GetExposureInUse(), colors->GetPointer(0));
  in.Colored = vtkSmartPointer<vtkPolyData>::New();
  in.Colored->ShallowCopy(data);
  in.Colored->GetPointData()->SetScalars(colors);
  in.ColoredFor = data->GetMTime();
  in.ColoredWeights = weights;
  in.ColoredExposure = this->GetExposureInUse();
  return in.Colored;
}

void vtkRadiosityRelightMapper::SumOnCpu(const std::vector<float>& weights, vtkFloatArray* linear)
{
  vtkPolyData* data = this->Internal->UploadedData;
  const vtkIdType points = data->GetNumberOfPoints();
  // The relight filter's sum (in parallel, on the arrays' own memory), as the shader's.
  std::string error = this->Internal->Problem.empty() ? "" : this->Internal->Problem;
  if (!error.empty() ||
    !this->Internal->Input.Combine(false, std::vector<double>(weights.begin(), weights.end()), linear, error))
  {
    vtkErrorMacro(<< "Cannot relight on the CPU: " << error << ".");
    linear->SetNumberOfComponents(3);
    linear->SetNumberOfTuples(points);
    linear->FillValue(0.0f);
  }
}

double vtkRadiosityRelightMapper::GetExposureInUse()
{
  // Metered as the relight filter meters: once per solution, with the lights at their
  // defaults, so that a light turned up brightens the picture; on the current lights only
  // where the defaults light nothing.
  Internals& in = *this->Internal;
  vtkPolyData* data = in.UploadedData;
  // Nothing to meter where the input has a problem, or changed since its tables were read
  // (their pointers would be stale): the last value stands until the next upload.
  if (in.Exposure > 0 || !data || !in.Problem.empty() || data->GetMTime() > in.UploadedTime)
  {
    return in.Exposure > 0 ? in.Exposure : in.Metered;
  }
  if (in.MeteredFor == data->GetMTime() && in.MeteredWeights.empty())
  {
    return in.Metered;
  }
  std::vector<float> defaults;
  for (const radiosity::Vec3& c : in.Defaults)
  {
    defaults.insert(defaults.end(), { static_cast<float>(c.x), static_cast<float>(c.y), static_cast<float>(c.z) });
  }
  vtkNew<vtkFloatArray> linear;
  this->SumOnCpu(defaults, linear);
  in.Metered = vtkRadiosityMeteredExposure(data, linear, false, 0.0);
  in.MeteredFor = data->GetMTime();
  in.MeteredWeights.clear();
  if (!(in.Metered > 0))
  {
    in.MeteredWeights = this->CurrentWeights();
    this->SumOnCpu(in.MeteredWeights, linear);
    in.Metered = vtkRadiosityMeteredExposure(data, linear, false);
  }
  return in.Metered;
}

vtkUnsignedCharArray* vtkRadiosityRelightMapper::MapScalars(double alpha)
{
  int cellFlag = 0;
  return this->MapScalars(alpha, cellFlag);
}

vtkUnsignedCharArray* vtkRadiosityRelightMapper::MapScalars(double alpha, int& cellFlag)
{
  vtkDataSet* drawn = this->Internal->OnCPU && this->CurrentInput ? this->CurrentInput : this->GetInput();
  return this->Superclass::MapScalars(drawn, alpha, cellFlag);
}

void vtkRadiosityRelightMapper::SetUseGPU(bool use)
{
  if (use != this->Internal->UseGPU)
  {
    this->Internal->UseGPU = use;
    this->Internal->UploadedData = nullptr; // decide again at the next render
  }
}

bool vtkRadiosityRelightMapper::GetUseGPU() const
{
  return this->Internal->UseGPU;
}

bool vtkRadiosityRelightMapper::GetRelitOnCPU() const
{
  return this->Internal->OnCPU;
}

void vtkRadiosityRelightMapper::RenderPieceFinish(vtkRenderer* ren, vtkActor* act)
{
  if (this->Internal->Texture->GetHandle())
  {
    this->Internal->Texture->Deactivate();
  }
  this->Superclass::RenderPieceFinish(ren, act);
}

bool vtkRadiosityRelightMapper::GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  const int lights = this->Internal->OnCPU ? -2 : this->GetNumberOfLights(); // -2: the CPU path's plain shader
  return this->Superclass::GetNeedToRebuildShaders(cellBO, ren, act) || this->Internal->ShaderLights != lights;
}

void vtkRadiosityRelightMapper::ReplaceShaderValues(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::ReplaceShaderValues(shaders, ren, act);
  const int k = this->GetNumberOfLights();
  this->Internal->ShaderLights = this->Internal->OnCPU ? -2 : k;
  if (ren->GetSelector() || this->Internal->OnCPU)
  {
    return; // picking draws ids, not colors; the CPU path draws its colors as scalars
  }
  Extend(shaders[vtkShader::Vertex], VertexDeclarations(k), VertexColor(k));
  Extend(shaders[vtkShader::Fragment], "in vec3 relightColor;\n", "  gl_FragData[0] = vec4(relightColor, 1.0);\n");
}

void vtkRadiosityRelightMapper::SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::SetMapperShaderParameters(cellBO, ren, act);
  Internals& in = *this->Internal;
  vtkShaderProgram* program = cellBO.Program;
  if (!program || !program->IsUniformUsed("relightSolutions"))
  {
    return;
  }
  std::vector<float> weights = this->CurrentWeights();
  weights.resize(std::max<size_t>(weights.size(), 3), 0.0f);
  if (in.Texture->GetHandle())
  {
    in.Texture->Activate();
    program->SetUniformi("relightSolutions", in.Texture->GetTextureUnit());
  }
  program->SetUniform3fv("relightWeights", static_cast<int>(weights.size() / 3), weights.data());
  program->SetUniformf("relightExposure", static_cast<float>(this->GetExposureInUse()));
}

void vtkRadiosityRelightMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Internal->Texture->ReleaseGraphicsResources(window);
  this->Internal->Buffer->ReleaseGraphicsResources();
  this->Internal->UploadedData = nullptr;
  this->Internal->ShaderLights = -1;
  this->Superclass::ReleaseGraphicsResources(window);
}

void vtkRadiosityRelightMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Exposure: " << this->Internal->Exposure << "\n";
  os << indent << "Lights: " << this->GetNumberOfLights() << ", uploads: " << this->Internal->Uploads << "\n";
}
