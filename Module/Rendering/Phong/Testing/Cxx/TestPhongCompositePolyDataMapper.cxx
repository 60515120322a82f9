// The composite path (what ParaView draws with): a multiblock of a floor and three
// spheres above it, one with its own block colour and one with point scalars (so two helpers draw
// it; then one with its own block opacity too), lit by a directional, a point and a spot light with
// a Blinn-Phong lobe sharper than vtkProperty allows. It must draw exactly what
// vtkPhongPolyDataMapper draws for the same blocks as separate actors (one implementation, two
// entry points), recompile on structure and not on values, and match the baseline.

#include "vtkPhongTestUtilities.h"

#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPhongCompositePolyDataMapper.h"

namespace
{
// Red to blue along x: point scalars, drawn directly as colours.
void AddColours(vtkPolyData* mesh)
{
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetName("Colours");
  colours->SetNumberOfComponents(3);
  double bounds[6];
  mesh->GetBounds(bounds);
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    const double t = (mesh->GetPoint(i)[0] - bounds[0]) / (bounds[1] - bounds[0]);
    colours->InsertNextTuple3(255.0 * (1.0 - t), 60.0, 255.0 * t);
  }
  mesh->GetPointData()->SetScalars(colours);
}
}

int TestPhongCompositePolyDataMapper(int argc, char* argv[])
{
  vtkPhongTest::Scene scene(400, 300);
  scene.Renderer->AutomaticLightCreationOff();
  const double white[3] = { 1.0, 1.0, 1.0 };
  const double warm[3] = { 1.0, 0.85, 0.6 };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  const double key[3] = { 1.0, 1.5, 2.0 };
  const double side[3] = { -1.5, 0.5, 1.0 };
  const double above[3] = { 0.3, 0.2, 2.5 };
  vtkPhongTest::AddLight(scene, key, origin, white, false)->SetIntensity(0.5);
  vtkLight* point = vtkPhongTest::AddLight(scene, side, origin, warm, true);
  point->SetConeAngle(180.0);
  point->SetAttenuationValues(1.0, 0.2, 0.0);
  vtkLight* spot = vtkPhongTest::AddLight(scene, above, origin, white, true);
  spot->SetConeAngle(20.0);
  spot->SetIntensity(0.45);

  auto sphere = vtkPhongTest::MakeSphere(48, 0.35);
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(4);
  blocks->SetBlock(0, vtkPhongTest::Moved(vtkPhongTest::MakePlane(1.3, 40), 0.0, 0.0, -0.45));
  blocks->SetBlock(1, vtkPhongTest::Moved(sphere, -0.8, 0.0, 0.0));
  blocks->SetBlock(2, vtkPhongTest::Moved(sphere, 0.0, 0.3, 0.0));
  auto coloured = vtkPhongTest::Moved(sphere, 0.8, 0.0, 0.0);
  AddColours(coloured);
  blocks->SetBlock(3, coloured);

  vtkNew<vtkPhongProperty> material;
  material->SetLightingModelToBlinnPhong();
  material->SetColor(0.8, 0.8, 0.75);
  material->SetAmbient(0.1);
  material->SetSpecular(0.6);
  material->SetShininess(300.0);
  material->SetInterpolationToPhong();

  vtkNew<vtkPhongCompositePolyDataMapper> composite;
  composite->SetInputDataObject(blocks);
  vtkNew<vtkCompositeDataDisplayAttributes> attributes;
  composite->SetCompositeDataDisplayAttributes(attributes);
  const double teal[3] = { 0.2, 0.7, 0.65 };
  attributes->SetBlockColor(blocks->GetBlock(2), teal);
  vtkNew<vtkActor> compositeActor;
  compositeActor->SetMapper(composite);
  compositeActor->SetProperty(material);
  scene.Renderer->AddActor(compositeActor);

  // The same blocks through the polydata mapper, one actor each.
  std::vector<vtkActor*> separate;
  for (unsigned int b = 0; b < blocks->GetNumberOfBlocks(); ++b)
  {
    vtkNew<vtkPhongProperty> blockMaterial;
    blockMaterial->DeepCopy(material);
    if (b == 2)
    {
      // A block colour replaces the ambient and diffuse colours, not the specular one.
      blockMaterial->SetAmbientColor(teal[0], teal[1], teal[2]);
      blockMaterial->SetDiffuseColor(teal[0], teal[1], teal[2]);
    }
    vtkActor* actor =
      vtkPhongTest::AddActor(scene, vtkPolyData::SafeDownCast(blocks->GetBlock(b)), blockMaterial);
    actor->VisibilityOff();
    separate.push_back(actor);
  }

  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->SetFocalPoint(0.0, 0.05, 0.0);
  camera->SetPosition(0.0, -2.2, 2.6);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(38.0);
  scene.Renderer->ResetCameraClippingRange();

  vtkPhongTest::Checks checks;
  vtkPhongTest::ErrorCollector errors;
  errors.Observe(composite);
  scene.Window->Render();
  auto fromComposite = vtkPhongTest::Snapshot(scene.Window);
  // The floor has texture coordinates, one sphere scalars: three kinds of block.
  checks.Expect(composite->GetNumberOfHelpers() == 3,
    "three helpers (floor, plain spheres, coloured sphere), got " +
      std::to_string(composite->GetNumberOfHelpers()));
  const std::string signature = composite->GetLastShaderSignature();
  checks.Expect(signature.find("directional 1 point 1 spot 1") != std::string::npos &&
      signature.find("LOBE_BLINN") != std::string::npos,
    "the helpers are lit by vtkPhong's shader, signature [" + signature + "]");
  const int variants = composite->GetNumberOfShaderVariants();
  checks.Expect(variants >= 2, "a lighting variant per helper, got " + std::to_string(variants));

  compositeActor->VisibilityOff();
  for (vtkActor* actor : separate)
  {
    actor->VisibilityOn();
  }
  scene.Window->Render();
  auto fromSeparateMappers = vtkPhongTest::Snapshot(scene.Window);
  const int largest = vtkPhongTest::MaxDifference(fromComposite, fromSeparateMappers);
  const int differing = vtkPhongTest::CountDifferentPixels(fromComposite, fromSeparateMappers, 1);
  std::cout << "composite against separate vtkPhongPolyDataMappers: max difference " << largest
            << " levels, " << differing << " pixels above 1 level\n";
  if (getenv("PHONG_DUMP"))
  {
    vtkNew<vtkPNGWriter> writer;
    writer->SetInputData(fromComposite);
    writer->SetFileName("/tmp/composite.png");
    writer->Write();
    writer->SetInputData(fromSeparateMappers);
    writer->SetFileName("/tmp/separate.png");
    writer->Write();
  }
  checks.Expect(largest <= 2 && differing <= 24,
    "the composite mapper draws what vtkPhongPolyDataMapper draws (max " + std::to_string(largest) +
      " levels, " + std::to_string(differing) + " pixels)");
  for (vtkActor* actor : separate)
  {
    actor->VisibilityOff();
  }
  compositeActor->VisibilityOn();

  // Values change uniforms only; the structure (a debug view) builds a variant.
  const int compiles = composite->GetShaderCompileCount();
  spot->SetColor(0.6, 0.9, 1.0);
  material->SetShininess(120.0);
  attributes->SetBlockColor(blocks->GetBlock(2), white);
  scene.Window->Render();
  checks.Expect(composite->GetShaderCompileCount() == compiles,
    "value changes recompiled (" + std::to_string(composite->GetShaderCompileCount()) +
      " compiles, was " + std::to_string(compiles) + ")");
  composite->SetDebugView(vtkPhongPolyDataMapper::ShadingNormal);
  scene.Window->Render();
  checks.Expect(composite->GetShaderCompileCount() > compiles &&
      std::string(composite->GetLastShaderSignature()).find("view 5") != std::string::npos,
    "the debug view builds its own variant");
  composite->SetDebugView(vtkPhongPolyDataMapper::Final);
  spot->SetColor(1.0, 1.0, 1.0);
  material->SetShininess(300.0);
  attributes->SetBlockColor(blocks->GetBlock(2), teal);

  // A block opacity reaches the lighting through VTK's opacityUniform, set per block between
  // the draws (vtkPhongBlockMapper.h): the composite draws what a separate mapper with that
  // opacity draws, and the floor shows through the sphere.
  attributes->SetBlockOpacity(blocks->GetBlock(1), 0.5);
  separate[1]->GetProperty()->SetOpacity(0.5);
  scene.Window->Render();
  auto translucentComposite = vtkPhongTest::Snapshot(scene.Window);
  compositeActor->VisibilityOff();
  for (vtkActor* actor : separate)
  {
    actor->VisibilityOn();
  }
  scene.Window->Render();
  auto translucentSeparate = vtkPhongTest::Snapshot(scene.Window);
  const int translucentLargest =
    vtkPhongTest::MaxDifference(translucentComposite, translucentSeparate);
  const int translucentDiffering =
    vtkPhongTest::CountDifferentPixels(translucentComposite, translucentSeparate, 1);
  const int opacityShows =
    vtkPhongTest::CountDifferentPixels(translucentComposite, fromComposite, 8);
  std::cout << "with a block opacity: max difference " << translucentLargest << " levels, "
            << translucentDiffering << " pixels above 1 level; " << opacityShows
            << " pixels changed by the opacity\n";
  checks.Expect(translucentLargest <= 2 && translucentDiffering <= 24 && opacityShows > 500,
    "a block opacity is drawn as a separate mapper draws that opacity (max " +
      std::to_string(translucentLargest) + " levels, " + std::to_string(translucentDiffering) +
      " pixels; " + std::to_string(opacityShows) + " pixels changed)");
  for (vtkActor* actor : separate)
  {
    actor->VisibilityOff();
  }
  compositeActor->VisibilityOn();
  attributes->SetBlockOpacity(blocks->GetBlock(1), 1.0); // Remove... does not mark a change
  separate[1]->GetProperty()->SetOpacity(1.0);

  scene.Window->Render();
  checks.Expect(errors.Messages.empty(), "no errors or warnings from the composite mapper");
  return vtkPhongTest::Finish(argc, argv, scene.Window, checks.Passed);
}
