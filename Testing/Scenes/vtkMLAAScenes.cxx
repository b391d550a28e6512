// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMLAAScenes.h"

#include "vtkActor.h"
#include "vtkArrowSource.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkConeSource.h"
#include "vtkContourFilter.h"
#include "vtkCubeSource.h"
#include "vtkCylinderSource.h"
#include "vtkElevationFilter.h"
#include "vtkGlyph3D.h"
#include "vtkImageActor.h"
#include "vtkImageMapper3D.h"
#include "vtkImageCanvasSource2D.h"
#include "vtkImageData.h"
#include "vtkImageProperty.h"
#include "vtkLineSource.h"
#include "vtkLookupTable.h"
#include "vtkMath.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointSource.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkQuadric.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSampleFunction.h"
#include "vtkScalarBarActor.h"
#include "vtkSphereSource.h"
#include "vtkSuperquadricSource.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkTexture.h"
#include "vtkTexturedSphereSource.h"
#include "vtkTrivialProducer.h"
#include "vtkTubeFilter.h"
#include "vtkWindowToImageFilter.h"

#include <cmath>
#include <functional>
#include <map>

namespace
{
vtkSmartPointer<vtkActor> AddActor(vtkRenderer* renderer, vtkAlgorithm* source,
  const double color[3], bool scalars = false)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  mapper->SetScalarVisibility(scalars);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(color[0], color[1], color[2]);
  renderer->AddActor(actor);
  return actor;
}

// Points the camera at everything in the scene, zoomed by `zoom`.
void FrameAll(vtkRenderer* renderer, double zoom)
{
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Zoom(zoom);
  renderer->ResetCameraClippingRange();
}

void Silhouettes(vtkRenderer* renderer)
{
  // Shaded solids: curved and straight silhouettes at every angle, against a light background.
  renderer->SetBackground(0.92, 0.93, 0.95);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(32);
  sphere->SetCenter(-1.2, 0.2, 0.0);
  const double red[3] = { 0.8, 0.25, 0.2 };
  AddActor(renderer, sphere, red);
  vtkNew<vtkCubeSource> cube;
  cube->SetCenter(1.1, 0.3, 0.0);
  const double blue[3] = { 0.2, 0.35, 0.75 };
  auto cubeActor = AddActor(renderer, cube, blue);
  cubeActor->RotateX(25.0);
  cubeActor->RotateY(35.0);
  vtkNew<vtkConeSource> cone;
  cone->SetResolution(48);
  cone->SetCenter(0.0, -1.1, 0.0);
  cone->SetDirection(1.0, 0.35, 0.2);
  const double green[3] = { 0.25, 0.6, 0.3 };
  AddActor(renderer, cone, green);
  renderer->GetActiveCamera()->SetPosition(0.3, 0.6, 8.0);
  renderer->GetActiveCamera()->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->ResetCameraClippingRange();
}

void Lines(vtkRenderer* renderer)
{
  // Spokes of 1-pixel lines and of 3-pixel lines at many angles: the worst case of staircases.
  renderer->SetBackground(1.0, 1.0, 1.0);
  for (int i = 0; i < 24; ++i)
  {
    const double angle = (i + 0.37) * 3.14159265358979 / 24.0;
    const bool thick = (i % 2) == 1;
    vtkNew<vtkLineSource> line;
    const double cx = thick ? 1.05 : -1.05;
    line->SetPoint1(cx, 0.0, 0.0);
    line->SetPoint2(cx + std::cos(angle), std::sin(angle), 0.0);
    const double dark[3] = { 0.1, 0.1, 0.15 };
    const double orange[3] = { 0.85, 0.4, 0.05 };
    auto actor = AddActor(renderer, line, thick ? orange : dark);
    actor->GetProperty()->SetLineWidth(thick ? 3.0f : 1.0f);
    actor->GetProperty()->LightingOff();
    vtkNew<vtkLineSource> mirrored;
    mirrored->SetPoint1(cx, 0.0, 0.0);
    mirrored->SetPoint2(cx - std::cos(angle), -std::sin(angle), 0.0);
    auto mirroredActor = AddActor(renderer, mirrored, thick ? orange : dark);
    mirroredActor->GetProperty()->SetLineWidth(thick ? 3.0f : 1.0f);
    mirroredActor->GetProperty()->LightingOff();
  }
  renderer->GetActiveCamera()->SetPosition(0.0, 0.0, 6.0);
  renderer->GetActiveCamera()->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->ResetCameraClippingRange();
}

void Wireframe(vtkRenderer* renderer)
{
  // A wireframe superquadric: dense 1-pixel mesh lines over a dark background.
  renderer->SetBackground(0.08, 0.09, 0.12);
  vtkNew<vtkSuperquadricSource> quadric;
  quadric->SetThetaResolution(24);
  quadric->SetPhiResolution(16);
  quadric->SetThetaRoundness(0.6);
  quadric->SetPhiRoundness(0.8);
  quadric->ToroidalOn();
  quadric->SetThickness(0.45);
  const double cyan[3] = { 0.55, 0.85, 1.0 };
  auto actor = AddActor(renderer, quadric, cyan);
  actor->GetProperty()->SetRepresentationToWireframe();
  actor->GetProperty()->LightingOff();
  actor->RotateX(60.0);
  actor->RotateY(20.0);
  renderer->GetActiveCamera()->SetPosition(0.0, 0.0, 4.2);
  renderer->GetActiveCamera()->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->ResetCameraClippingRange();
}

void IsoSurface(vtkRenderer* renderer)
{
  // Nested iso-surfaces of a quadric, coloured by scalar: smooth shading and silhouettes
  // against each other.
  renderer->SetBackground(0.2, 0.22, 0.28);
  vtkNew<vtkQuadric> quadric;
  quadric->SetCoefficients(0.5, 1.0, 0.2, 0.0, 0.1, 0.0, 0.0, 0.2, 0.0, 0.0);
  vtkNew<vtkSampleFunction> sample;
  sample->SetSampleDimensions(40, 40, 40);
  sample->SetImplicitFunction(quadric);
  sample->ComputeNormalsOff();
  vtkNew<vtkContourFilter> contours;
  contours->SetInputConnection(sample->GetOutputPort());
  contours->GenerateValues(4, 0.0, 1.2);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(contours->GetOutputPort());
  mapper->SetScalarRange(0.0, 1.2);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetOpacity(1.0);
  renderer->AddActor(actor);
  actor->RotateY(30.0);
  actor->RotateX(-20.0);
  FrameAll(renderer, 1.3);
}

void Glyphs(vtkRenderer* renderer)
{
  // Arrow glyphs on a grid of points: many small shapes with short edges.
  renderer->SetBackground(0.97, 0.97, 0.94);
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(11, 8);
  plane->SetOrigin(-2.0, -1.5, 0.0);
  plane->SetPoint1(2.0, -1.5, 0.0);
  plane->SetPoint2(-2.0, 1.5, 0.0);
  vtkNew<vtkArrowSource> arrow;
  arrow->SetTipResolution(16);
  arrow->SetShaftResolution(12);
  vtkNew<vtkGlyph3D> glyphs;
  glyphs->SetInputConnection(plane->GetOutputPort());
  glyphs->SetSourceConnection(arrow->GetOutputPort());
  glyphs->SetScaleFactor(0.3);
  glyphs->OrientOn();
  glyphs->SetVectorModeToUseNormal();
  const double purple[3] = { 0.45, 0.25, 0.65 };
  auto actor = AddActor(renderer, glyphs, purple);
  actor->RotateX(-50.0);
  actor->RotateZ(15.0);
  renderer->GetActiveCamera()->SetPosition(0.0, -0.5, 6.5);
  renderer->GetActiveCamera()->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->ResetCameraClippingRange();
}

// An 8 x 8 checkerboard texture (256 x 256 texels, nearest-neighbour lookups).
vtkSmartPointer<vtkTexture> Checkerboard()
{
  vtkNew<vtkImageCanvasSource2D> canvas;
  canvas->SetScalarTypeToUnsignedChar();
  canvas->SetNumberOfScalarComponents(3);
  canvas->SetExtent(0, 255, 0, 255, 0, 0);
  canvas->SetDrawColor(235, 235, 225);
  canvas->FillBox(0, 255, 0, 255);
  canvas->SetDrawColor(40, 60, 110);
  for (int i = 0; i < 8; ++i)
  {
    for (int j = 0; j < 8; ++j)
    {
      if ((i + j) % 2 == 0)
      {
        canvas->FillBox(i * 32, i * 32 + 31, j * 32, j * 32 + 31);
      }
    }
  }
  auto texture = vtkSmartPointer<vtkTexture>::New();
  texture->SetInputConnection(canvas->GetOutputPort());
  texture->InterpolateOff();
  return texture;
}

void Texture(vtkRenderer* renderer)
{
  // A checkerboard texture on a tilted plane and a sphere: edges inside textures, which
  // geometric antialiasing (MSAA) does not see.
  renderer->SetBackground(0.3, 0.3, 0.32);
  vtkSmartPointer<vtkTexture> texture = Checkerboard();
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-2.0, -2.0, 0.0);
  plane->SetPoint1(2.0, -2.0, 0.0);
  plane->SetPoint2(-2.0, 2.0, 0.0);
  const double white[3] = { 1.0, 1.0, 1.0 };
  auto planeActor = AddActor(renderer, plane, white);
  planeActor->SetTexture(texture);
  planeActor->RotateX(-62.0);
  planeActor->GetProperty()->LightingOff();
  vtkNew<vtkTexturedSphereSource> sphere;
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(24);
  sphere->SetRadius(0.7);
  auto sphereActor = AddActor(renderer, sphere, white);
  sphereActor->SetTexture(texture);
  sphereActor->SetPosition(0.9, 0.6, 0.8);
  renderer->GetActiveCamera()->SetPosition(0.0, 0.0, 6.0);
  renderer->GetActiveCamera()->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->ResetCameraClippingRange();
}

void TextAndScalarBar(vtkRenderer* renderer)
{
  // Text and a scalar bar over a coloured surface: overlays must come out untouched.
  renderer->SetBackground(1.0, 1.0, 1.0);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(24);
  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.66, 0.0);
  lut->Build();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  mapper->SetLookupTable(lut);
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray("Normals");
  mapper->SetScalarRange(-1.0, 1.0);
  mapper->ScalarVisibilityOn();
  mapper->ColorByArrayComponent("Normals", 2);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
  vtkNew<vtkTextActor> title;
  title->SetInput("Pressure at t = 0.25 s (MLAA)");
  title->GetTextProperty()->SetFontSize(20);
  title->GetTextProperty()->SetColor(0.1, 0.1, 0.1);
  title->SetPosition(12, 12);
  renderer->AddActor2D(title);
  vtkNew<vtkScalarBarActor> bar;
  bar->SetLookupTable(lut);
  bar->SetTitle("p [kPa]");
  bar->SetNumberOfLabels(5);
  bar->GetTitleTextProperty()->SetColor(0.1, 0.1, 0.1);
  bar->GetLabelTextProperty()->SetColor(0.1, 0.1, 0.1);
  bar->SetPosition(0.84, 0.1);
  bar->SetWidth(0.12);
  bar->SetHeight(0.8);
  renderer->AddActor2D(bar);
  renderer->GetActiveCamera()->SetPosition(-0.5, 0.6, 3.4);
  renderer->GetActiveCamera()->SetFocalPoint(0.1, 0.0, 0.0);
  renderer->ResetCameraClippingRange();
}

void Mixed(vtkRenderer* renderer)
{
  // Everything at once: a shaded body, its wireframe, points and a label.
  renderer->SetBackground(0.15, 0.16, 0.2);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(20);
  sphere->SetPhiResolution(12);
  const double gold[3] = { 0.9, 0.7, 0.3 };
  auto body = AddActor(renderer, sphere, gold);
  body->SetScale(1.4, 1.0, 1.0);
  auto wire = AddActor(renderer, sphere, gold);
  wire->SetScale(1.4, 1.0, 1.0);
  wire->SetPosition(1.8, 0.0, 0.0);
  wire->GetProperty()->SetRepresentationToWireframe();
  wire->GetProperty()->LightingOff();
  vtkNew<vtkCylinderSource> cylinder;
  cylinder->SetResolution(32);
  const double teal[3] = { 0.2, 0.7, 0.7 };
  auto cyl = AddActor(renderer, cylinder, teal);
  cyl->SetPosition(-1.9, 0.0, 0.0);
  cyl->RotateZ(30.0);
  cyl->RotateX(20.0);
  vtkNew<vtkPointSource> points;
  points->SetNumberOfPoints(60);
  points->SetRadius(2.8);
  points->SetDistributionToShell();
  const double white[3] = { 1.0, 1.0, 1.0 };
  auto pointActor = AddActor(renderer, points, white);
  pointActor->GetProperty()->SetRepresentationToPoints();
  pointActor->GetProperty()->SetPointSize(3.0f);
  pointActor->GetProperty()->LightingOff();
  vtkNew<vtkTextActor> label;
  label->SetInput("mixed scene");
  label->GetTextProperty()->SetFontSize(18);
  label->GetTextProperty()->SetColor(0.9, 0.9, 0.9);
  label->SetPosition(10, 10);
  renderer->AddActor2D(label);
  renderer->GetActiveCamera()->SetPosition(0.0, 1.0, 9.0);
  renderer->GetActiveCamera()->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->ResetCameraClippingRange();
}

void EqualLumaColormap(vtkRenderer* renderer)
{
  // Surfaces colour-mapped with a banded lookup table whose colours all have the same Rec. 709
  // luma (0.45 within 0.01): the band boundaries are edges that luma cannot see, the
  // silhouettes against the dark background edges that it can. Unlit, as a 2D plot or a
  // flat-shaded map would be.
  renderer->SetBackground(0.12, 0.12, 0.14);
  const double bands[][3] = { { 0.9, 0.36, 0.0 }, { 0.1, 0.5, 1.0 }, { 0.75, 0.32, 0.9 },
    { 0.2, 0.55, 0.2 }, { 1.0, 0.28, 0.5 }, { 0.0, 0.575, 0.5 } };
  vtkNew<vtkLookupTable> lut;
  lut->SetNumberOfTableValues(6);
  for (int i = 0; i < 6; ++i)
  {
    lut->SetTableValue(i, bands[i][0], bands[i][1], bands[i][2], 1.0);
  }
  lut->SetTableRange(0.0, 1.0);
  auto addMapped = [renderer, &lut](vtkAlgorithm* source, const double low[3],
                     const double high[3], double repeat) {
    vtkNew<vtkElevationFilter> elevation;
    elevation->SetInputConnection(source->GetOutputPort());
    elevation->SetLowPoint(low[0], low[1], low[2]);
    elevation->SetHighPoint(high[0], high[1], high[2]);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(elevation->GetOutputPort());
    mapper->SetLookupTable(lut);
    mapper->SetScalarRange(0.0, 1.0 / repeat);
    mapper->InterpolateScalarsBeforeMappingOn(); // sharp band boundaries inside triangles
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->GetProperty()->LightingOff();
    renderer->AddActor(actor);
    return actor;
  };
  // A tilted plane whose bands run at a few degrees off the horizontal, and a sphere with
  // curved bands.
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-2.6, -1.9, -0.5);
  plane->SetPoint1(0.4, -1.9, -0.5);
  plane->SetPoint2(-2.6, 1.9, -0.5);
  plane->SetResolution(60, 60);
  const double planeLow[3] = { 0.0, -1.9, 0.0 };
  const double planeHigh[3] = { 0.1, 1.9, 0.0 };
  addMapped(plane, planeLow, planeHigh, 1.0);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(96);
  sphere->SetPhiResolution(64);
  sphere->SetRadius(1.3);
  sphere->SetCenter(1.2, 0.0, 0.0);
  const double sphereLow[3] = { 0.3, -1.0, -1.0 };
  const double sphereHigh[3] = { 2.0, 1.3, 1.0 };
  addMapped(sphere, sphereLow, sphereHigh, 1.0);
  renderer->GetActiveCamera()->SetPosition(0.0, 0.0, 7.5);
  renderer->GetActiveCamera()->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->ResetCameraClippingRange();
}

void Horizon(vtkRenderer* renderer)
{
  // Long, nearly horizontal and nearly vertical edges: the horizon of a large ground plane seen
  // with the camera rolled by 1 degree, a beam across the view at 3 degrees and a mast at 88:
  // staircases whose steps are tens of pixels long, longer than the default search.
  renderer->SetBackground(0.55, 0.7, 0.9);
  vtkNew<vtkPlaneSource> ground;
  ground->SetOrigin(-200.0, 0.0, -200.0);
  ground->SetPoint1(200.0, 0.0, -200.0);
  ground->SetPoint2(-200.0, 0.0, 200.0);
  const double earth[3] = { 0.3, 0.35, 0.2 };
  auto groundActor = AddActor(renderer, ground, earth);
  groundActor->GetProperty()->LightingOff();
  vtkNew<vtkCubeSource> beam;
  beam->SetXLength(14.0);
  beam->SetYLength(0.25);
  beam->SetZLength(0.25);
  const double steel[3] = { 0.75, 0.3, 0.2 };
  auto beamActor = AddActor(renderer, beam, steel);
  beamActor->GetProperty()->LightingOff();
  beamActor->SetPosition(0.0, 1.6, -4.0);
  beamActor->RotateZ(3.0);
  vtkNew<vtkCubeSource> mast;
  mast->SetXLength(0.2);
  mast->SetYLength(8.0);
  mast->SetZLength(0.2);
  const double white[3] = { 0.95, 0.95, 0.9 };
  auto mastActor = AddActor(renderer, mast, white);
  mastActor->GetProperty()->LightingOff();
  mastActor->SetPosition(-2.5, 2.0, -6.0);
  mastActor->RotateZ(-2.0);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, 1.2, 6.0);
  camera->SetFocalPoint(0.0, 1.0, -20.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->Roll(1.0);
  renderer->ResetCameraClippingRange();
}

void ThinStructures(vtkRenderer* renderer)
{
  // Thin structures that point sampling breaks up: iso-lines of a 2D field drawn as 1-pixel
  // lines, streamline-like curves drawn as tubes about 0.6 pixel wide at 600 pixels of height,
  // and two "power lines" (cylinders of 0.85 pixel) across the view. Parallel projection keeps
  // their widths independent of depth.
  renderer->SetBackground(0.96, 0.95, 0.92);
  const double pixel = 3.0 / 600.0; // world units per pixel at 600 pixels of height
  vtkNew<vtkQuadric> field;
  field->SetCoefficients(1.0, 0.6, 0.0, 0.3, 0.0, 0.0, 0.2, -0.1, 0.0, 0.0);
  vtkNew<vtkSampleFunction> sample;
  sample->SetImplicitFunction(field);
  sample->SetModelBounds(-2.0, 0.3, -1.4, 1.4, 0.0, 0.0);
  sample->SetSampleDimensions(160, 160, 1);
  sample->ComputeNormalsOff();
  vtkNew<vtkContourFilter> isolines;
  isolines->SetInputConnection(sample->GetOutputPort());
  isolines->GenerateValues(10, 0.05, 2.0);
  const double ink[3] = { 0.15, 0.2, 0.45 };
  auto isoActor = AddActor(renderer, isolines, ink);
  isoActor->GetProperty()->LightingOff();
  // Streamline-like curves: y = y0 + a sin(k x + phase), as polylines.
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  for (int c = 0; c < 9; ++c)
  {
    const int n = 200;
    lines->InsertNextCell(n);
    for (int i = 0; i < n; ++i)
    {
      const double x = 0.4 + 1.7 * i / (n - 1.0);
      const double y = -1.2 + 0.3 * c + 0.12 * std::sin(3.0 * x + 0.7 * c);
      lines->InsertCellPoint(points->InsertNextPoint(x, y, 0.0));
    }
  }
  vtkNew<vtkPolyData> curves;
  curves->SetPoints(points);
  curves->SetLines(lines);
  vtkNew<vtkTubeFilter> tubes;
  tubes->SetInputData(curves);
  tubes->SetRadius(0.3 * pixel);
  tubes->SetNumberOfSides(6);
  const double red[3] = { 0.75, 0.15, 0.1 };
  auto tubeActor = AddActor(renderer, tubes, red);
  tubeActor->GetProperty()->LightingOff();
  for (int k = 0; k < 2; ++k)
  {
    vtkNew<vtkLineSource> wire;
    wire->SetPoint1(-2.1, 1.25 - 0.15 * k, 0.1);
    wire->SetPoint2(2.1, 1.05 - 0.35 * k, 0.1);
    vtkNew<vtkTubeFilter> cable;
    cable->SetInputConnection(wire->GetOutputPort());
    cable->SetRadius(0.42 * pixel);
    cable->SetNumberOfSides(6);
    const double black[3] = { 0.05, 0.05, 0.05 };
    auto cableActor = AddActor(renderer, cable, black);
    cableActor->GetProperty()->LightingOff();
  }
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetParallelScale(1.5);
  camera->SetPosition(0.0, 0.0, 5.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->ResetCameraClippingRange();
}

void Orbit(vtkRenderer* renderer)
{
  // What a slow camera orbit makes flicker: 1-pixel lines (a helix and straight wires), 2-pixel
  // points, small cone glyphs and a textured floor seen at a grazing angle.
  renderer->SetBackground(0.93, 0.94, 0.96);
  vtkNew<vtkPlaneSource> floor;
  floor->SetOrigin(-3.0, -3.0, 0.0);
  floor->SetPoint1(3.0, -3.0, 0.0);
  floor->SetPoint2(-3.0, 3.0, 0.0);
  const double white[3] = { 1.0, 1.0, 1.0 };
  auto floorActor = AddActor(renderer, floor, white);
  floorActor->SetTexture(Checkerboard());
  floorActor->GetProperty()->LightingOff();

  vtkNew<vtkPlaneSource> grid;
  grid->SetOrigin(-2.0, -2.0, 0.3);
  grid->SetPoint1(2.0, -2.0, 0.3);
  grid->SetPoint2(-2.0, 2.0, 0.3);
  grid->SetResolution(6, 6);
  vtkNew<vtkConeSource> cone;
  cone->SetResolution(12);
  cone->SetDirection(0.0, 0.0, 1.0);
  vtkNew<vtkGlyph3D> glyphs;
  glyphs->SetInputConnection(grid->GetOutputPort());
  glyphs->SetSourceConnection(cone->GetOutputPort());
  glyphs->SetScaleFactor(0.35);
  glyphs->OrientOff();
  const double orange[3] = { 0.9, 0.45, 0.1 };
  AddActor(renderer, glyphs, orange);

  // A helix of 1-pixel line segments and points along a spiral above the floor (fixed
  // positions, no random numbers).
  vtkNew<vtkPoints> helixPoints;
  vtkNew<vtkCellArray> helixLine;
  const int helixCount = 400;
  helixLine->InsertNextCell(helixCount);
  vtkNew<vtkPoints> spiralPoints;
  vtkNew<vtkCellArray> spiralVertices;
  for (int i = 0; i < helixCount; ++i)
  {
    const double t = i / (helixCount - 1.0);
    const double angle = 2.0 * vtkMath::Pi() * 5.0 * t;
    helixLine->InsertCellPoint(
      helixPoints->InsertNextPoint(1.2 * std::cos(angle), 1.2 * std::sin(angle), 0.2 + 1.6 * t));
    const double radius = 0.2 + 2.6 * t;
    spiralVertices->InsertNextCell(1);
    spiralVertices->InsertCellPoint(spiralPoints->InsertNextPoint(
      radius * std::cos(3.0 * angle), radius * std::sin(3.0 * angle), 0.05));
  }
  vtkNew<vtkPolyData> helix;
  helix->SetPoints(helixPoints);
  helix->SetLines(helixLine);
  vtkNew<vtkPolyDataMapper> helixMapper;
  helixMapper->SetInputData(helix);
  vtkNew<vtkActor> helixActor;
  helixActor->SetMapper(helixMapper);
  helixActor->GetProperty()->SetColor(0.1, 0.2, 0.5);
  helixActor->GetProperty()->LightingOff();
  renderer->AddActor(helixActor);
  vtkNew<vtkPolyData> spiral;
  spiral->SetPoints(spiralPoints);
  spiral->SetVerts(spiralVertices);
  vtkNew<vtkPolyDataMapper> spiralMapper;
  spiralMapper->SetInputData(spiral);
  vtkNew<vtkActor> spiralActor;
  spiralActor->SetMapper(spiralMapper);
  spiralActor->GetProperty()->SetColor(0.7, 0.1, 0.3);
  spiralActor->GetProperty()->SetPointSize(2.0f);
  spiralActor->GetProperty()->LightingOff();
  renderer->AddActor(spiralActor);

  // Straight wires across the scene.
  for (int k = 0; k < 4; ++k)
  {
    vtkNew<vtkLineSource> wire;
    wire->SetPoint1(-3.0, -2.5 + 1.5 * k, 1.0 + 0.2 * k);
    wire->SetPoint2(3.0, -2.0 + 1.3 * k, 1.2 + 0.1 * k);
    const double dark[3] = { 0.15, 0.15, 0.15 };
    AddActor(renderer, wire, dark)->GetProperty()->LightingOff();
  }
  renderer->GetActiveCamera()->SetPosition(0.0, -7.5, 4.5);
  renderer->GetActiveCamera()->SetFocalPoint(0.0, 0.0, 0.6);
  renderer->GetActiveCamera()->SetViewUp(0.0, 0.0, 1.0);
  renderer->ResetCameraClippingRange();
}

void PointCloud(vtkRenderer* renderer)
{
  // Particles drawn as square points of 1, 2 and 3 pixels, as a point cloud or a particle
  // tracer's output is shown: over the plain background on the left, and over a lit, shaded
  // sphere (smooth shading behind them) on the right. Clouds of random points from fixed seeds,
  // so that every program renders the same picture.
  renderer->SetBackground(0.95, 0.95, 0.97);
  vtkNew<vtkSphereSource> backdrop;
  backdrop->SetThetaResolution(64);
  backdrop->SetPhiResolution(32);
  backdrop->SetRadius(1.5);
  backdrop->SetCenter(1.5, 0.0, -1.5);
  const double stone[3] = { 0.55, 0.6, 0.68 };
  AddActor(renderer, backdrop, stone);
  struct Cloud
  {
    double Center[3];
    double Radius;
    int Points;
    float Size;
    double Color[3];
    int Seed;
  };
  const Cloud clouds[] = {
    { { -1.6, 0.4, 0.0 }, 1.0, 900, 1.0f, { 0.1, 0.15, 0.4 }, 11 },
    { { -1.2, -0.6, 0.0 }, 0.9, 300, 2.0f, { 0.8, 0.35, 0.05 }, 12 },
    { { -0.4, 0.2, 0.0 }, 0.8, 120, 3.0f, { 0.2, 0.55, 0.25 }, 13 },
    { { 1.5, 0.2, 0.2 }, 1.1, 900, 1.0f, { 0.98, 0.95, 0.6 }, 14 },
    { { 1.4, -0.4, 0.2 }, 1.0, 300, 2.0f, { 0.7, 0.1, 0.15 }, 15 },
    { { 1.8, 0.5, 0.2 }, 0.8, 120, 3.0f, { 0.05, 0.05, 0.1 }, 16 },
  };
  for (const Cloud& cloud : clouds)
  {
    vtkNew<vtkMinimalStandardRandomSequence> random;
    random->SetSeed(cloud.Seed);
    vtkNew<vtkPointSource> points;
    points->SetRandomSequence(random);
    points->SetCenter(cloud.Center[0], cloud.Center[1], cloud.Center[2]);
    points->SetRadius(cloud.Radius);
    points->SetNumberOfPoints(cloud.Points);
    points->SetDistributionToUniform();
    auto actor = AddActor(renderer, points, cloud.Color);
    actor->GetProperty()->SetRepresentationToPoints();
    actor->GetProperty()->SetPointSize(cloud.Size);
    actor->GetProperty()->LightingOff();
  }
  renderer->GetActiveCamera()->SetPosition(0.0, 0.0, 7.0);
  renderer->GetActiveCamera()->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->ResetCameraClippingRange();
}

// Held-out scenes (vtkMLAAScenes::HeldOutNames): kinds of pictures the main set does not have,
// kept out of the default lists so that nothing is tuned on them.

void SurfaceWithEdges(vtkRenderer* renderer)
{
  // ParaView's "Surface With Edges": a shaded superquadric with its mesh edges drawn over it
  // (VTK 9.1 draws such edges in the surface's fragment shader, already smoothed).
  renderer->SetBackground(0.32, 0.34, 0.43);
  vtkNew<vtkSuperquadricSource> quadric;
  quadric->SetThetaResolution(18);
  quadric->SetPhiResolution(12);
  quadric->SetThetaRoundness(0.3);
  quadric->SetPhiRoundness(1.4);
  const double sand[3] = { 0.9, 0.85, 0.7 };
  auto actor = AddActor(renderer, quadric, sand);
  actor->GetProperty()->EdgeVisibilityOn();
  actor->GetProperty()->SetEdgeColor(0.1, 0.1, 0.3);
  actor->RotateX(35.0);
  actor->RotateY(-25.0);
  FrameAll(renderer, 1.4);
}

void Molecule(vtkRenderer* renderer)
{
  // Shaded spheres coloured by position over black: overlapping silhouettes, and dark spheres
  // whose shaded rims fade into the background.
  renderer->SetBackground(0.0, 0.0, 0.0);
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(77);
  vtkNew<vtkPointSource> atoms;
  atoms->SetRandomSequence(random);
  atoms->SetRadius(1.3);
  atoms->SetNumberOfPoints(140);
  atoms->SetDistributionToUniform();
  vtkNew<vtkElevationFilter> position;
  position->SetInputConnection(atoms->GetOutputPort());
  position->SetLowPoint(-1.3, -1.3, 0.0);
  position->SetHighPoint(1.3, 1.3, 0.0);
  vtkNew<vtkSphereSource> ball;
  ball->SetThetaResolution(24);
  ball->SetPhiResolution(16);
  vtkNew<vtkGlyph3D> glyphs;
  glyphs->SetInputConnection(position->GetOutputPort());
  glyphs->SetSourceConnection(ball->GetOutputPort());
  glyphs->SetScaleFactor(0.28);
  glyphs->SetScaleModeToDataScalingOff();
  glyphs->SetColorModeToColorByScalar();
  vtkNew<vtkLookupTable> colors;
  colors->SetHueRange(0.6, 0.0);
  colors->SetValueRange(0.25, 0.9);
  colors->Build();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(glyphs->GetOutputPort());
  mapper->SetScalarRange(0.0, 1.0);
  mapper->SetLookupTable(colors);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
  FrameAll(renderer, 1.3);
}

void Terrain(vtkRenderer* renderer)
{
  // A height field coloured by elevation, seen obliquely, with 1-pixel contour lines on it:
  // slopes, smooth colour ramps and curved thin lines.
  renderer->SetBackground(0.75, 0.82, 0.9);
  const int n = 120;
  vtkNew<vtkPoints> points;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const double x = -2.0 + 4.0 * i / (n - 1.0);
      const double y = -2.0 + 4.0 * j / (n - 1.0);
      const double hill = std::exp(-2.0 * ((x - 0.5) * (x - 0.5) + y * y));
      points->InsertNextPoint(x, y, 0.35 * std::sin(1.7 * x) * std::cos(1.3 * y) + 0.25 * hill);
    }
  }
  vtkNew<vtkCellArray> quads;
  for (int j = 0; j + 1 < n; ++j)
  {
    for (int i = 0; i + 1 < n; ++i)
    {
      const vtkIdType quad[4] = { j * n + i, j * n + i + 1, (j + 1) * n + i + 1, (j + 1) * n + i };
      quads->InsertNextCell(4, quad);
    }
  }
  vtkNew<vtkPolyData> surface;
  surface->SetPoints(points);
  surface->SetPolys(quads);
  vtkNew<vtkElevationFilter> elevation;
  elevation->SetInputData(surface);
  elevation->SetLowPoint(0.0, 0.0, -0.6);
  elevation->SetHighPoint(0.0, 0.0, 0.6);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(elevation->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
  vtkNew<vtkContourFilter> contours;
  contours->SetInputConnection(elevation->GetOutputPort());
  contours->GenerateValues(12, 0.05, 0.95);
  const double ink[3] = { 0.1, 0.1, 0.1 };
  auto lines = AddActor(renderer, contours, ink);
  lines->GetProperty()->LightingOff();
  lines->SetPosition(0.0, 0.0, 0.004); // just above the surface
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, -5.0, 3.2);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 0.0, 1.0);
  renderer->ResetCameraClippingRange();
}

void Streamlines(vtkRenderer* renderer)
{
  // Forty curved 1-pixel polylines traced through a swirling field, in perspective over white.
  renderer->SetBackground(1.0, 1.0, 1.0);
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  for (int c = 0; c < 40; ++c)
  {
    const int n = 300;
    lines->InsertNextCell(n);
    double x = -1.5 + 3.0 * ((c * 37) % 40) / 40.0;
    double y = -1.2 + 2.4 * ((c * 13) % 40) / 40.0;
    double z = 0.3 * std::sin(c);
    for (int i = 0; i < n; ++i)
    {
      lines->InsertCellPoint(points->InsertNextPoint(x, y, z));
      const double vx = -y + 0.3 * std::sin(2.0 * z);
      const double vy = 0.8 * x + 0.2;
      const double vz = 0.2 * std::cos(x);
      const double step = 0.012 / (std::sqrt(vx * vx + vy * vy + vz * vz) + 1e-9);
      x += step * vx;
      y += step * vy;
      z += step * vz;
    }
  }
  vtkNew<vtkPolyData> curves;
  curves->SetPoints(points);
  curves->SetLines(lines);
  vtkNew<vtkTrivialProducer> producer;
  producer->SetOutput(curves);
  const double blue[3] = { 0.1, 0.25, 0.6 };
  auto actor = AddActor(renderer, producer, blue);
  actor->GetProperty()->LightingOff();
  actor->RotateX(-30.0);
  FrameAll(renderer, 1.2);
}

// An nx x ny image of random values shown straight on by an image actor without interpolation
// (voxels as ParaView and VTK show a slice with nearest-neighbour sampling), framed by a parallel
// camera whose view is `scale` times the image's height. With `lookupTable`, the values are a
// smooth field plus noise coloured by it, and a colour legend stands beside the image; without,
// every voxel has a random colour. Issue 50.
void VoxelImage(vtkRenderer* renderer, int nx, int ny, double scale, bool lookupTable, int seed)
{
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(seed);
  vtkNew<vtkImageData> image;
  image->SetDimensions(nx, ny, 1);
  image->AllocateScalars(lookupTable ? VTK_FLOAT : VTK_UNSIGNED_CHAR, lookupTable ? 1 : 3);
  for (int y = 0; y < ny; ++y)
  {
    for (int x = 0; x < nx; ++x)
    {
      if (lookupTable)
      {
        const double field = std::sin(0.21 * x) * std::cos(0.17 * y);
        image->SetScalarComponentFromDouble(x, y, 0, 0, field + 0.4 * (random->GetValue() - 0.5));
        random->Next();
        continue;
      }
      for (int c = 0; c < 3; ++c)
      {
        image->SetScalarComponentFromDouble(x, y, 0, c, std::floor(256.0 * random->GetValue()));
        random->Next();
      }
    }
  }
  vtkNew<vtkImageActor> actor;
  actor->GetMapper()->SetInputData(image);
  actor->InterpolateOff();
  vtkNew<vtkLookupTable> lut;
  if (lookupTable)
  {
    lut->SetHueRange(0.66, 0.0);
    lut->SetTableRange(-1.2, 1.2);
    lut->Build();
    actor->GetProperty()->SetLookupTable(lut);
    actor->GetProperty()->UseLookupTableScalarRangeOn();
    vtkNew<vtkScalarBarActor> bar;
    bar->SetLookupTable(lut);
    bar->SetNumberOfLabels(4);
    bar->GetLabelTextProperty()->SetColor(1.0, 1.0, 1.0);
    bar->SetPosition(0.86, 0.1);
    bar->SetWidth(0.1);
    bar->SetHeight(0.8);
    renderer->AddActor2D(bar);
  }
  renderer->AddViewProp(actor);
  renderer->SetBackground(0.1, 0.1, 0.12);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(0.5 * (nx - 1), 0.5 * (ny - 1), 0.0);
  camera->SetPosition(0.5 * (nx - 1), 0.5 * (ny - 1), 10.0 * ny);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetParallelScale(0.5 * ny * scale);
  renderer->ResetCameraClippingRange();
}

// 32 x 24 voxels filling a 4:3 viewport: at 800 x 600 (or any multiple of 32 x 24) every voxel
// side lies on a pixel boundary and nothing is aliased, so every change is damage.
void Voxels(vtkRenderer* renderer)
{
  VoxelImage(renderer, 32, 24, 1.0, false, 5);
}

// A slice of 45 x 30 values through a colour map, zoomed by a factor that puts some voxel sides
// between pixel boundaries, beside its colour legend.
void ImageSlice(vtkRenderer* renderer)
{
  VoxelImage(renderer, 45, 30, 1.13, true, 11);
}

struct Scene
{
  std::string Description;
  std::function<void(vtkRenderer*)> Build;
  bool AxisAligned = false; // vtkMLAAScenes::AxisAligned
};

const std::vector<std::pair<std::string, Scene>>& Scenes()
{
  static const std::vector<std::pair<std::string, Scene>> scenes = {
    { "silhouettes", { "shaded sphere, cube and cone", Silhouettes } },
    { "lines", { "1- and 3-pixel lines at 48 angles", Lines } },
    { "wireframe", { "wireframe torus-like superquadric", Wireframe } },
    { "isosurface", { "four nested iso-surfaces of a quadric", IsoSurface } },
    { "glyphs", { "arrow glyphs on a tilted grid", Glyphs } },
    { "texture", { "checkerboard texture on a plane and a sphere", Texture } },
    { "text", { "coloured sphere with text and a scalar bar", TextAndScalarBar } },
    { "mixed", { "shaded, wireframe and point geometry with a label", Mixed } },
    { "colormap", { "surfaces banded by a lookup table of equal-luma colours", EqualLumaColormap } },
    { "horizon", { "long edges at 1 to 3 degrees off horizontal and vertical", Horizon } },
    { "thin", { "1-pixel iso-lines, sub-pixel streamline tubes and power lines", ThinStructures } },
    { "orbit", { "1-pixel lines, points and cone glyphs over a textured floor", Orbit } },
    { "points", { "point clouds of 1-, 2- and 3-pixel points on a plain and a shaded background",
                  PointCloud } },
    { "voxels", { "32 x 24 random voxels seen straight on, filling the view (no interpolation)",
                  Voxels, true } },
  };
  return scenes;
}

const std::vector<std::pair<std::string, Scene>>& HeldOutScenes()
{
  static const std::vector<std::pair<std::string, Scene>> scenes = {
    { "surface-edges",
      { "a shaded superquadric with its mesh edges drawn over it (ParaView's Surface With Edges)",
        SurfaceWithEdges } },
    { "molecule", { "140 shaded spheres coloured by position over black", Molecule } },
    { "terrain",
      { "an elevation-coloured height field seen obliquely, with 1-pixel contour lines",
        Terrain } },
    { "streamlines", { "forty curved 1-pixel polylines in perspective over white", Streamlines } },
    { "image-slice",
      { "a 45 x 30 slice through a colour map, zoomed without interpolation, with its legend",
        ImageSlice } },
  };
  return scenes;
}

// The scene called `name`, in either list; null for an unknown name.
const Scene* Find(const std::string& name)
{
  for (const auto* list : { &Scenes(), &HeldOutScenes() })
  {
    for (const auto& scene : *list)
    {
      if (scene.first == name)
      {
        return &scene.second;
      }
    }
  }
  return nullptr;
}
}

namespace vtkMLAAScenes
{
std::vector<std::string> Names()
{
  std::vector<std::string> names;
  for (const auto& scene : Scenes())
  {
    names.push_back(scene.first);
  }
  return names;
}

std::vector<std::string> HeldOutNames()
{
  std::vector<std::string> names;
  for (const auto& scene : HeldOutScenes())
  {
    names.push_back(scene.first);
  }
  return names;
}

std::string Describe(const std::string& name)
{
  const Scene* scene = Find(name);
  return scene ? scene->Description : std::string();
}

bool AxisAligned(const std::string& name)
{
  const Scene* scene = Find(name);
  return scene && scene->AxisAligned;
}

bool Build(const std::string& name, vtkRenderer* renderer)
{
  const Scene* scene = Find(name);
  if (scene)
  {
    scene->Build(renderer);
  }
  return scene != nullptr;
}

vtkSmartPointer<vtkRenderWindow> NewOffscreenWindow(int width, int height)
{
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(width, height);
  return window;
}

vtkSmartPointer<vtkImageData> Capture(vtkRenderWindow* window, bool alpha)
{
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  if (alpha)
  {
    grab->SetInputBufferTypeToRGBA();
  }
  else
  {
    grab->SetInputBufferTypeToRGB();
  }
  grab->ShouldRerenderOff();
  grab->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(grab->GetOutput());
  return image;
}
}
