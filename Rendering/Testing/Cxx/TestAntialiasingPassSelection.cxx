// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Hardware selection through the pass, for every method of PassMethods(): while a
// vtkHardwareSelector renders the ids of props, cells and points into the colour buffer, the pass
// must not antialias them (a blend of two encoded ids is a third, wrong id). On two spheres, an
// area selection of cells (the whole window and its left half) and of points, a pixel query at an
// edge of the big sphere, and a vtkRenderedAreaPicker give the same ids with the pass as without
// it, and after the selection the pass antialiases again exactly as before; the same on the
// silhouettes scene. No errors are reported on the way.
#include "vtkAntialiasingRenderTestUtilities.h"

#include "vtkActor.h"
#include "vtkInformation.h"
#include "vtkHardwareSelector.h"
#include "vtkIdTypeArray.h"
#include "vtkPolyDataMapper.h"
#include "vtkProp3DCollection.h"
#include "vtkProperty.h"
#include "vtkRenderedAreaPicker.h"
#include "vtkSelection.h"
#include "vtkSelectionNode.h"
#include "vtkSphereSource.h"

#include <set>

using namespace vtkMLAATest;

namespace
{
struct Selected
{
  std::set<vtkIdType> Cells;
  std::set<vtkIdType> Points;
  std::set<vtkIdType> Left; // cells in the left half
  vtkIdType EdgeCell = -2;  // the cell under a pixel on the sphere's silhouette
  vtkIdType EdgeProp = -2;
  int PickedProps = 0; // props picked by vtkRenderedAreaPicker
};

Selected Select(vtkRenderer* renderer, int width, int height, const unsigned int edgePixel[2],
  MessageObserver* messages)
{
  Selected s;
  vtkNew<vtkHardwareSelector> selector;
  messages->Watch(selector);
  selector->SetRenderer(renderer);
  selector->SetFieldAssociation(vtkDataObject::FIELD_ASSOCIATION_CELLS);
  selector->SetArea(0, 0, width - 1, height - 1);
  vtkSmartPointer<vtkSelection> cells;
  cells.TakeReference(selector->Select());
  s.Cells = SelectedIds(cells);

  selector->SetArea(0, 0, width / 2 - 1, height - 1);
  vtkSmartPointer<vtkSelection> left;
  left.TakeReference(selector->Select());
  s.Left = SelectedIds(left);

  // A pixel query: the buffers of a full-window capture.
  selector->SetArea(0, 0, width - 1, height - 1);
  if (selector->CaptureBuffers())
  {
    const vtkHardwareSelector::PixelInformation info = selector->GetPixelInformation(edgePixel);
    s.EdgeCell = info.Valid ? info.AttributeID : -1;
    s.EdgeProp = info.Valid ? info.PropID : -1;
    selector->ClearBuffers();
  }

  selector->SetFieldAssociation(vtkDataObject::FIELD_ASSOCIATION_POINTS);
  vtkSmartPointer<vtkSelection> points;
  points.TakeReference(selector->Select());
  s.Points = SelectedIds(points);

  vtkNew<vtkRenderedAreaPicker> picker;
  picker->AreaPick(0, 0, width - 1, height - 1, renderer);
  s.PickedProps = picker->GetProp3Ds()->GetNumberOfItems();
  return s;
}

// Two spheres (two props) over a white background.
void Spheres(const PassMethod& method, MessageObserver* messages)
{
  const int width = 300, height = 300;
  auto window = vtkMLAAScenes::NewOffscreenWindow(width, height);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  renderer->SetBackground(1.0, 1.0, 1.0);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(24);
  sphere->SetPhiResolution(16);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.8, 0.3, 0.2);
  renderer->AddActor(actor);
  // A second prop, so that prop ids matter too.
  vtkNew<vtkSphereSource> small;
  small->SetCenter(0.6, 0.4, 0.3);
  small->SetRadius(0.2);
  vtkNew<vtkPolyDataMapper> smallMapper;
  smallMapper->SetInputConnection(small->GetOutputPort());
  vtkNew<vtkActor> smallActor;
  smallActor->SetMapper(smallMapper);
  renderer->AddActor(smallActor);
  renderer->ResetCamera();
  auto plain = vtkMLAAScenes::Capture(window);

  // A pixel just inside the big sphere's silhouette on the middle row: the last one, from the
  // left, whose colour is not the background.
  unsigned int edgePixel[2] = { 0, height / 2 };
  for (int x = 0; x < width; ++x)
  {
    if (GetValue(plain, x, height / 2, 0) != 255.0 || GetValue(plain, x, height / 2, 1) != 255.0)
    {
      edgePixel[0] = x;
      break;
    }
  }

  const Selected expected = Select(renderer, width, height, edgePixel, messages);
  std::cout << method.Name << " without the pass: " << expected.Cells.size() << " cells, "
            << expected.Left.size() << " in the left half, " << expected.Points.size()
            << " points; pixel (" << edgePixel[0] << ", " << edgePixel[1] << "): prop " << expected.EdgeProp << ", cell "
            << expected.EdgeCell << "; area picker: " << expected.PickedProps << " props"
            << std::endl;
  MLAA_CHECK(expected.Cells.size() > 100);
  MLAA_CHECK(expected.Left.size() > 20 && expected.Left.size() < expected.Cells.size());
  MLAA_CHECK(expected.Points.size() > 50);
  MLAA_CHECK(expected.EdgeCell >= 0);
  MLAA_CHECK(expected.PickedProps == 2);

  auto pass = method.Use(renderer);
  messages->Watch(pass);
  auto antialiased = vtkMLAAScenes::Capture(window);
  MLAA_CHECK(Compare(plain, antialiased, 0.0).Pixels > 100);

  const Selected got = Select(renderer, width, height, edgePixel, messages);
  std::cout << method.Name << " with the pass: " << got.Cells.size() << " cells, " << got.Left.size()
            << " in the left half, " << got.Points.size() << " points; pixel: prop "
            << got.EdgeProp << ", cell " << got.EdgeCell << "; area picker: " << got.PickedProps
            << " props" << std::endl;
  MLAA_CHECK(got.Cells == expected.Cells);
  MLAA_CHECK(got.Left == expected.Left);
  MLAA_CHECK(got.Points == expected.Points);
  MLAA_CHECK(got.EdgeCell == expected.EdgeCell && got.EdgeProp == expected.EdgeProp);
  MLAA_CHECK(got.PickedProps == expected.PickedProps);

  // The selection left the pass as it was: the next render is antialiased as before.
  auto after = vtkMLAAScenes::Capture(window);
  MLAA_CHECK(Compare(antialiased, after, 0.0).Count == 0);
  StopPass(renderer, window);
}

// The silhouettes scene: the same selection with and without the pass.
void Silhouettes(const PassMethod& method, MessageObserver* messages)
{
  SceneWindow scene("silhouettes", 300, 200);
  const unsigned int pixel[2] = { 150, 100 };
  const Selected expected = Select(scene.Renderer, 300, 200, pixel, messages);
  auto pass = method.Use(scene.Renderer);
  messages->Watch(pass);
  auto antialiased = vtkMLAAScenes::Capture(scene.Window);
  MLAA_CHECK(Compare(scene.Plain, antialiased, 0.0).Pixels > 50);
  const Selected got = Select(scene.Renderer, 300, 200, pixel, messages);
  std::cout << "silhouettes: " << expected.Cells.size() << " cells without the pass, "
            << got.Cells.size() << " with it" << std::endl;
  MLAA_CHECK(!expected.Cells.empty() && got.Cells == expected.Cells);
  MLAA_CHECK(got.Left == expected.Left && got.Points == expected.Points);
  MLAA_CHECK(got.EdgeCell == expected.EdgeCell && got.EdgeProp == expected.EdgeProp);
  MLAA_CHECK(got.PickedProps == expected.PickedProps);
  MLAA_CHECK(Compare(antialiased, vtkMLAAScenes::Capture(scene.Window), 0.0).Count == 0);
}
}

int TestAntialiasingPassSelection(int, char*[])
{
  ForEachPassMethod([](const PassMethod& method, MessageObserver* messages) {
    Spheres(method, messages);
    Silhouettes(method, messages);
  });
  return Result();
}
