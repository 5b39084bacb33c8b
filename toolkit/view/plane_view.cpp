// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "view/plane_view.h"

#include <pcl/visualization/pcl_visualizer.h>
#include <vtkActor.h>
#include <vtkAppendPolyData.h>
#include <vtkArrowSource.h>
#include <vtkBillboardTextActor3D.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkImageData.h>
#include <vtkLODActor.h>
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkOutputWindow.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTextProperty.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iostream>
#include <stdexcept>
#include <vector>

#include "view/display_check.h"

namespace floodplane::view {
namespace {

constexpr int kMinimumSize = 16;
constexpr int kMaximumSize = 8192;
constexpr double kPointSizeAtCloudHeight = 2.0;  // pixels per point when the image is as tall as the grid
constexpr double kOutlineWidth = 2.0;
constexpr double kArrowAmbient = 0.6;  // with diffuse 0.4: lit arrows stay within 60-100 % of white
constexpr int kWindowWidth = 960;
constexpr int kWindowHeight = 720;
constexpr const char* kKeyHelp = "n normals   z unlabelled   b outlines   v sensor/oblique   r reset   q quit";

struct ImageSize {
  int width = 0;
  int height = 0;
};

// Collects VTK's error messages while it is installed as VTK's output window, so that a
// failure becomes an exception instead of text on stderr and a black image. Warnings are
// kept away from the user's terminal too; they do not fail the rendering.
class ErrorCollector : public vtkOutputWindow {
 public:
  // What vtkStandardNewMacro would define. No vtkTypeMacro: nothing asks this class for its
  // VTK type, and the macro's trailing definitions do not survive clang-format.
  static ErrorCollector* New() {
    auto* collector = new ErrorCollector;
    collector->InitializeObjectBase();
    return collector;
  }
  void DisplayErrorText(const char* text) override { errors_.emplace_back(text); }
  void DisplayWarningText(const char*) override {}
  void DisplayGenericWarningText(const char*) override {}
  void DisplayText(const char*) override {}
  void DisplayDebugText(const char*) override {}
  const std::vector<std::string>& errors() const { return errors_; }

 private:
  std::vector<std::string> errors_;
};

// Installs an ErrorCollector for its lifetime and puts the previous output window back.
// VTK's logger writes to stderr besides the output window (Debian's VTK 9.1 warns there about
// its own calls of deprecated shader methods, a dozen lines a rendering): it is silenced for
// good, as the apps have no use for it and VTK cannot say what it was set to.
class CollectVtkErrors {
 public:
  CollectVtkErrors() : previous_(vtkOutputWindow::GetInstance()) {
    vtkOutputWindow::SetInstance(collector_);
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  }
  ~CollectVtkErrors() { vtkOutputWindow::SetInstance(previous_); }
  CollectVtkErrors(const CollectVtkErrors&) = delete;
  CollectVtkErrors& operator=(const CollectVtkErrors&) = delete;

  // Throws the first error VTK reported, on one line.
  void throwIfAny() const {
    if (collector_->errors().empty()) return;
    std::string first = collector_->errors().front();
    std::replace(first.begin(), first.end(), '\n', ' ');
    throw std::runtime_error("VTK: " + first);
  }

 private:
  vtkSmartPointer<vtkOutputWindow> previous_;
  vtkNew<ErrorCollector> collector_;
};

void requireRendering() {
  if (const std::optional<std::string> reason = renderingUnavailableReason()) throw std::runtime_error(*reason);
}

void setColour(vtkProperty* property, const std::array<std::uint8_t, 3>& colour) {
  property->SetColor(colour[0] / 255.0, colour[1] / 255.0, colour[2] / 255.0);
}

// Half way to white: an outline stands out against its plane's points in the plane's hue.
std::array<std::uint8_t, 3> outlineColour(std::uint32_t colour_label) {
  std::array<std::uint8_t, 3> colour = pointColour(colour_label);
  for (std::uint8_t& channel : colour) channel = static_cast<std::uint8_t>((channel + 255) / 2);
  return colour;
}

// The finite points whose colour label is (`unlabelled`) or is not 0, as vertices with a
// colour each.
vtkSmartPointer<vtkLODActor> pointActor(const PlaneScene& scene, bool unlabelled, double point_size) {
  vtkNew<vtkPoints> points;
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetNumberOfComponents(3);
  colours->SetName("colours");
  vtkNew<vtkCellArray> vertices;
  const pcl::PointCloud<pcl::PointXYZ>& cloud = *scene.cloud;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const pcl::PointXYZ& p = cloud[i];
    if ((scene.colour_labels[i] == 0) != unlabelled) continue;
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) continue;
    const vtkIdType id = points->InsertNextPoint(p.x, p.y, p.z);
    vertices->InsertNextCell(1, &id);
    const std::array<std::uint8_t, 3> colour = pointColour(scene.colour_labels[i]);
    colours->InsertNextTypedTuple(colour.data());
  }
  vtkNew<vtkPolyData> data;
  data->SetPoints(points);
  data->SetVerts(vertices);
  data->GetPointData()->SetScalars(colours);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(data);
  mapper->SetColorModeToDirectScalars();
  auto actor = vtkSmartPointer<vtkLODActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetPointSize(static_cast<float>(point_size));
  actor->GetProperty()->LightingOff();  // the palette's colours, exactly
  return actor;
}

// One arrow per plane, from the centroid along the normal (arrowTip).
vtkSmartPointer<vtkActor> arrowActor(const PlaneScene& scene, float longest_arrow) {
  vtkNew<vtkArrowSource> arrow;  // along +x from 0 to 1
  arrow->SetShaftRadius(0.05);
  arrow->SetTipRadius(0.12);
  arrow->SetTipLength(0.3);
  arrow->SetShaftResolution(16);
  arrow->SetTipResolution(16);
  vtkNew<vtkAppendPolyData> arrows;
  for (const PlaneMarker& plane : scene.planes) {
    const double length = (arrowTip(plane, longest_arrow) - plane.centroid).norm();
    if (!(length > 0.0)) continue;
    const Eigen::Vector3d normal = plane.normal.cast<double>().normalized();
    const Eigen::Vector3d axis = Eigen::Vector3d::UnitX().cross(normal);
    const double angle = std::atan2(axis.norm(), normal.x()) * 180.0 / 3.14159265358979323846;
    vtkNew<vtkTransform> transform;
    transform->Translate(plane.centroid.x(), plane.centroid.y(), plane.centroid.z());
    if (axis.norm() > 1e-9) {
      transform->RotateWXYZ(angle, axis.x(), axis.y(), axis.z());
    } else if (normal.x() < 0.0) {
      transform->RotateWXYZ(180.0, 0.0, 0.0, 1.0);
    }
    transform->Scale(length, length, length);
    vtkNew<vtkTransformPolyDataFilter> placed;
    placed->SetInputConnection(arrow->GetOutputPort());
    placed->SetTransform(transform);
    placed->Update();
    arrows->AddInputData(placed->GetOutput());
  }
  vtkNew<vtkPolyDataMapper> mapper;
  if (arrows->GetNumberOfInputConnections(0) > 0) mapper->SetInputConnection(arrows->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  setColour(actor->GetProperty(), kArrowColour);
  actor->GetProperty()->SetAmbient(kArrowAmbient);
  actor->GetProperty()->SetDiffuse(1.0 - kArrowAmbient);
  actor->GetProperty()->SetSpecular(0.0);
  return actor;
}

// Puts `text` beyond the tip of its arrow as `camera` sees it, so that it does not cover the
// arrow: to the right of a tip pointing right, above a tip pointing up, and so on.
void placeBeyondTip(vtkBillboardTextActor3D* text, const Eigen::Vector3f& centroid, const Eigen::Vector3f& tip,
                    const Camera& camera, const ImageSize& size, int gap) {
  const auto base_pixel = projectToPixel(camera, centroid.cast<double>(), size.width, size.height);
  const auto tip_pixel = projectToPixel(camera, tip.cast<double>(), size.width, size.height);
  const Eigen::Vector2d direction =
      base_pixel && tip_pixel ? Eigen::Vector2d(*tip_pixel - *base_pixel) : Eigen::Vector2d(1.0, 0.0);
  vtkTextProperty* style = text->GetTextProperty();
  if (std::abs(direction.x()) >= std::abs(direction.y())) {
    const bool right = direction.x() >= 0.0;
    right ? style->SetJustificationToLeft() : style->SetJustificationToRight();
    style->SetVerticalJustificationToCentered();
    text->SetDisplayOffset(right ? gap : -gap, 0);
  } else {
    const bool up = direction.y() < 0.0;  // image rows go down, display coordinates up
    style->SetJustificationToCentered();
    up ? style->SetVerticalJustificationToBottom() : style->SetVerticalJustificationToTop();
    text->SetDisplayOffset(0, up ? gap : -gap);
  }
}

// "<id>: <inliers>" beyond each arrow's tip, facing the camera at a fixed pixel size.
std::vector<vtkSmartPointer<vtkProp>> textActors(const PlaneScene& scene, float longest_arrow, const Camera& camera,
                                                 const ImageSize& size) {
  std::vector<vtkSmartPointer<vtkProp>> actors;
  if (!scene.show_plane_text) return actors;
  const int font_size = std::max(10, size.height / 48);
  for (const PlaneMarker& plane : scene.planes) {
    auto text = vtkSmartPointer<vtkBillboardTextActor3D>::New();
    text->SetInput((std::to_string(plane.id) + ": " + std::to_string(plane.inliers)).c_str());
    const Eigen::Vector3f tip = arrowTip(plane, longest_arrow);
    text->SetPosition(tip.x(), tip.y(), tip.z());
    vtkTextProperty* style = text->GetTextProperty();
    style->SetFontSize(font_size);
    style->SetColor(1.0, 1.0, 1.0);
    style->SetBackgroundColor(0.0, 0.0, 0.0);
    style->SetBackgroundOpacity(0.6);
    placeBeyondTip(text, plane.centroid, tip, camera, size, font_size / 3);
    actors.push_back(text);
  }
  return actors;
}

// Each plane's outline as a closed line in a lighter shade of the plane's colour.
vtkSmartPointer<vtkActor> outlineActor(const PlaneScene& scene) {
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetNumberOfComponents(3);
  for (const PlaneMarker& plane : scene.planes) {
    if (plane.outline.size() < 2) continue;
    const std::array<std::uint8_t, 3> colour = outlineColour(plane.colour_label);
    std::vector<vtkIdType> ids;
    for (const Eigen::Vector3f& p : plane.outline) {
      ids.push_back(points->InsertNextPoint(p.x(), p.y(), p.z()));
      colours->InsertNextTypedTuple(colour.data());
    }
    ids.push_back(ids.front());
    lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  vtkNew<vtkPolyData> data;
  data->SetPoints(points);
  data->SetLines(lines);
  data->GetPointData()->SetScalars(colours);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(data);
  mapper->SetColorModeToDirectScalars();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetLineWidth(static_cast<float>(kOutlineWidth));
  actor->GetProperty()->LightingOff();
  return actor;
}

// Everything drawn for one scene, grouped by what the keys toggle.
struct SceneActors {
  vtkSmartPointer<vtkLODActor> planes;
  vtkSmartPointer<vtkLODActor> unlabelled;
  vtkSmartPointer<vtkActor> arrows;
  std::vector<vtkSmartPointer<vtkProp>> texts;
  vtkSmartPointer<vtkActor> outlines;

  void addTo(vtkRenderer* renderer) const {
    renderer->AddActor(planes);
    renderer->AddActor(unlabelled);
    renderer->AddActor(arrows);
    renderer->AddActor(outlines);
    for (const auto& text : texts) renderer->AddActor(text);
  }
  void show(const Layers& layers) const {
    unlabelled->SetVisibility(layers.unlabelled);
    arrows->SetVisibility(layers.normals);
    for (const auto& text : texts) text->SetVisibility(layers.normals);
    outlines->SetVisibility(layers.outlines);
  }
};

// The actors of `scene` for an image of `size`; `camera` decides on which side of each arrow
// its text goes.
SceneActors sceneActors(const PlaneScene& scene, const Camera& camera, const ImageSize& size) {
  if (!scene.cloud || scene.colour_labels.size() != scene.cloud->size()) {
    throw std::invalid_argument("plane view: the scene needs a cloud and a colour label per point");
  }
  // Points a little larger than a pixel of the grid, so surfaces seen at an angle stay closed.
  const double point_size =
      std::max(1.0, std::round(kPointSizeAtCloudHeight * size.height / std::max<double>(1.0, scene.cloud->height)));
  const float longest_arrow = longestArrow(*scene.cloud);
  return {pointActor(scene, false, point_size), pointActor(scene, true, point_size), arrowActor(scene, longest_arrow),
          textActors(scene, longest_arrow, camera, size), outlineActor(scene)};
}

void applyCamera(vtkRenderer* renderer, const Camera& camera) {
  vtkCamera* vtk_camera = renderer->GetActiveCamera();
  vtk_camera->SetPosition(camera.position.data());
  vtk_camera->SetFocalPoint(camera.focal_point.data());
  vtk_camera->SetViewUp(camera.view_up.data());
  vtk_camera->SetViewAngle(camera.view_angle_deg);
  vtk_camera->OrthogonalizeViewUp();
  renderer->ResetCameraClippingRange();
}

// The window's pixels, top row first (VTK's images start at the bottom).
floodplane::io::RgbImage grabImage(vtkRenderWindow* window) {
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkImageData* image = grab->GetOutput();
  int dimensions[3] = {0, 0, 0};
  image->GetDimensions(dimensions);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  if (scalars == nullptr || scalars->GetNumberOfComponents() != 3 || dimensions[0] <= 0 || dimensions[1] <= 0) {
    throw std::runtime_error("VTK gave no RGB image of the rendering");
  }
  floodplane::io::RgbImage out;
  out.width = static_cast<std::size_t>(dimensions[0]);
  out.height = static_cast<std::size_t>(dimensions[1]);
  out.pixels.resize(out.width * out.height * 3);
  const auto* bytes = static_cast<const std::uint8_t*>(image->GetScalarPointer());
  const std::size_t row_bytes = out.width * 3;
  for (std::size_t row = 0; row < out.height; ++row) {
    std::memcpy(out.pixels.data() + row * row_bytes, bytes + (out.height - 1 - row) * row_bytes, row_bytes);
  }
  return out;
}

void checkSize(int width, int height) {
  if (width < kMinimumSize || height < kMinimumSize || width > kMaximumSize || height > kMaximumSize) {
    throw std::invalid_argument("image size " + std::to_string(width) + "x" + std::to_string(height) + " is outside " +
                                std::to_string(kMinimumSize) + ".." + std::to_string(kMaximumSize));
  }
}

}  // namespace

floodplane::io::RgbImage renderImage(const PlaneScene& scene, CameraView view, int width, int height,
                                     const Layers& layers) {
  checkSize(width, height);
  const Camera camera = sceneCamera(scene, view, static_cast<double>(width) / height);
  requireRendering();
  CollectVtkErrors errors;
  const SceneActors actors = sceneActors(scene, camera, {width, height});
  actors.show(layers);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.0, 0.0, 0.0);
  actors.addTo(renderer);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);  // no smoothing: the palette's colours stay exact
  window->SetSize(width, height);
  window->AddRenderer(renderer);
  applyCamera(renderer, camera);
  window->Render();
  errors.throwIfAny();
  floodplane::io::RgbImage image = grabImage(window);
  errors.throwIfAny();
  if (image.width != static_cast<std::size_t>(width) || image.height != static_cast<std::size_t>(height)) {
    throw std::runtime_error("VTK rendered " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                             " instead of " + std::to_string(width) + "x" + std::to_string(height));
  }
  return image;
}

void showWindow(const PlaneScene& scene, const std::string& title) {
  const Camera sensor_camera = sceneCamera(scene, CameraView::sensor);
  const Camera oblique_camera =
      sceneCamera(scene, CameraView::oblique, static_cast<double>(kWindowWidth) / kWindowHeight);
  requireRendering();
  CollectVtkErrors errors;
  pcl::visualization::PCLVisualizer viewer(title);
  viewer.setSize(kWindowWidth, kWindowHeight);
  viewer.setBackgroundColor(0.0, 0.0, 0.0);
  vtkRenderer* renderer = viewer.getRendererCollection()->GetFirstRenderer();
  const SceneActors actors = sceneActors(scene, sensor_camera, {kWindowWidth, kWindowHeight});
  Layers layers;
  actors.show(layers);
  actors.addTo(renderer);
  // In PCL's map of clouds, the points answer its + and - keys (point size).
  (*viewer.getCloudActorMap())["planes"].actor = actors.planes;
  (*viewer.getCloudActorMap())["unlabelled"].actor = actors.unlabelled;
  viewer.addText(kKeyHelp, 10, 10, 14, 0.8, 0.8, 0.8, "keys");
  applyCamera(renderer, sensor_camera);
  bool oblique = false;
  viewer.registerKeyboardCallback([&](const pcl::visualization::KeyboardEvent& event) {
    if (!event.keyDown()) return;
    switch (event.getKeyCode()) {
      case 'n':
        layers.normals = !layers.normals;
        break;
      case 'z':
        layers.unlabelled = !layers.unlabelled;
        break;
      case 'b':
        layers.outlines = !layers.outlines;
        break;
      case 'v':
        oblique = !oblique;
        applyCamera(renderer, oblique ? oblique_camera : sensor_camera);
        break;
      default:
        return;
    }
    actors.show(layers);
    viewer.getRenderWindow()->Render();
  });
  std::cout << "keys: " << kKeyHelp << std::endl;
  viewer.spin();
  viewer.close();
  errors.throwIfAny();
}

}  // namespace floodplane::view
