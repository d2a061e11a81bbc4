// Writes the seed corpora of the fuzz harnesses into DIR/<harness>/: small meshes through VTK's
// own PLY and STL writers (ASCII and binary, with and without normals and texture coordinates),
// OFF files, a default session through the session writer, and every declared parameter's
// default spelled as the CLI reads it, and material libraries (.mtl) of every statement the MTL
// reader knows, spelt as the format's specification and its PBR extension write them.
// Usage: fuzz_make_seeds DIR
#include "core/image/image.h"
#include "core/parameters/parameters.h"
#include "scene/SceneModel.h"
#include "scene/Session.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"

#include <QJsonDocument>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vtkCellArray.h>
#include <vtkPLYWriter.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSTLWriter.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>

namespace fs = std::filesystem;

namespace
{
// OFF has no VTK writer; the format is a header line, counts, points and faces.
void writeOff(vtkPolyData* mesh, const fs::path& path, bool normals)
{
  std::ofstream out(path);
  out << (normals ? "NOFF\n" : "OFF\n") << mesh->GetNumberOfPoints() << ' '
      << mesh->GetNumberOfPolys() << " 0\n";
  vtkDataArray* n = mesh->GetPointData()->GetNormals();
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    out << p[0] << ' ' << p[1] << ' ' << p[2];
    if (normals && n)
    {
      double v[3];
      n->GetTuple(i, v);
      out << ' ' << v[0] << ' ' << v[1] << ' ' << v[2];
    }
    out << '\n';
  }
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  mesh->GetPolys()->InitTraversal();
  while (mesh->GetPolys()->GetNextCell(count, ids))
  {
    out << count;
    for (vtkIdType k = 0; k < count; ++k)
    {
      out << ' ' << ids[k];
    }
    out << '\n';
  }
}
} // namespace

int main(int argc, char** argv)
{
  if (argc != 2)
  {
    std::fprintf(stderr, "usage: fuzz_make_seeds DIR\n");
    return 2;
  }
  const fs::path dir = argv[1];
  for (const char* sub :
       {"ply", "stl", "off", "session", "text_values", "image", "material_library", "mtl"})
  {
    fs::create_directories(dir / sub);
  }
  // Small meshes: seeds should be quick to mutate.
  vtkSmartPointer<vtkPolyData> sphere = aniso::makeSphere(8, 4);
  vtkSmartPointer<vtkPolyData> plate = aniso::makePlate(2);
  int index = 0;
  for (vtkPolyData* mesh : {sphere.Get(), plate.Get()})
  {
    for (bool binary : {false, true})
    {
      const std::string stem = std::to_string(index++);
      vtkNew<vtkPLYWriter> ply;
      ply->SetInputData(mesh);
      binary ? ply->SetFileTypeToBinary() : ply->SetFileTypeToASCII();
      ply->SetFileName((dir / "ply" / (stem + ".ply")).string().c_str());
      ply->Write();
      vtkNew<vtkSTLWriter> stl;
      stl->SetInputData(mesh);
      binary ? stl->SetFileTypeToBinary() : stl->SetFileTypeToASCII();
      stl->SetFileName((dir / "stl" / (stem + ".stl")).string().c_str());
      stl->Write();
      writeOff(mesh, dir / "off" / (stem + ".off"), binary);
    }
  }
  {
    aniso::SceneModel model;
    const QByteArray json =
        QJsonDocument(aniso::sessionToJson(model, {}, QString())).toJson(QJsonDocument::Indented);
    std::ofstream(dir / "session" / "default.aniso", std::ios::binary)
        .write(json.constData(), json.size());
    // A scene of two parts of different materials (the parts and materials sections).
    aniso::ScenePart shaft = aniso::partOfMesh("builtin:sphere", "turned brass");
    aniso::ScenePart base = aniso::partOfMesh("builtin:plate", "brushed steel");
    base.visible = false;
    base.group = "assembly";
    model.setParts({shaft, base}, aniso::builtinMaterials());
    const QByteArray parts =
        QJsonDocument(aniso::sessionToJson(model, {}, QString())).toJson(QJsonDocument::Indented);
    std::ofstream(dir / "session" / "parts.aniso", std::ios::binary)
        .write(parts.constData(), parts.size());
  }
  {
    // The built-in metals through the library writer.
    const std::string text = aniso::materialLibraryToJson(aniso::builtinMaterials());
    std::ofstream(dir / "material_library" / "builtin.json", std::ios::binary) << text;
  }
  {
    // Material libraries: a Phong material as VTK's OBJ exporter writes one, metallic-roughness
    // keys of the PBR extension, textures with their options.
    std::ofstream(dir / "mtl" / "phong.mtl", std::ios::binary)
        << "# wavefront mtl file\n\nnewmtl mtl1\nKa 0 0 0\nKd 0.8 0.2 0.1\nKs 0.45 0.425 "
           "0.35\nNs 40\nTr 1\nillum 3\n";
    std::ofstream(dir / "mtl" / "pbr.mtl", std::ios::binary)
        << "newmtl brushed\nKd 0.9 0.8 0.5\nPr 0.3\nPm 0.75\nPs 0.1\naniso 0.8\nanisor "
           "0.25\nd 1\nmap_Pm metal.png\nmap_Pr rough.png\nnorm -bm 1 normal.png\n";
    std::ofstream(dir / "mtl" / "textures.mtl", std::ios::binary)
        << "newmtl a\r\nKd 1\r\nmap_Kd -s 2 2 1 -o 0.5 -clamp on tex\\albedo map.png\r\n"
           "map_Bump -bm 0.5 -imfchan l height.png\r\nbump h.png\r\nmap_Ks -mm 0 1 s.png\r\n"
           "map_Ns -texres 512 -blendu off n.png\r\nnewmtl b\r\nKs 0.04\r\nNs 1000\r\n";
  }
  const auto& specs = aniso::parameterSpecs();
  for (size_t i = 0; i < specs.size(); ++i)
  {
    const std::string text = aniso::formatParameterValue(specs[i], aniso::defaultParameterValue(specs[i]));
    std::ofstream out(dir / "text_values" / (std::string(specs[i].name) + ".txt"), std::ios::binary);
    out.put(static_cast<char>(i));
    out << text;
  }
  for (const char* brushing : {"uv", "axis:0,0,1", "around:1,0,0@0.5,0,0", "radial:0,1,0"})
  {
    std::ofstream out(dir / "text_values" / (std::string("brushing-") + brushing[0] + ".txt"),
                      std::ios::binary);
    out.put(static_cast<char>(specs.size()));
    out << brushing;
  }
  // Images through OpenImageIO's writers (writeImage), the first byte naming the extension as
  // fuzz_image reads it; small, with a gradient so that compressed formats have content.
  {
    aniso::Image image;
    image.width = 6;
    image.height = 4;
    image.channels = 4;
    image.data.resize(std::size_t(6) * 4 * 4);
    for (std::size_t i = 0; i < image.data.size(); ++i)
    {
      image.data[i] = static_cast<float>(i % 7) / 6.0f;
    }
    const char* const suffixes[] = {".exr", ".hdr", ".png", ".tif", ".jpg"};
    for (int k = 0; k < 5; ++k)
    {
      const fs::path written = dir / "image" / (std::string("written") + suffixes[k]);
      try
      {
        aniso::writeImage(written.string(), image);
      }
      catch (const std::exception&)
      {
        continue; // a format writeImage does not write (JPEG): no seed of it
      }
      std::ifstream in(written, std::ios::binary);
      const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      std::ofstream out(dir / "image" / (std::string("seed") + std::to_string(k)), std::ios::binary);
      out.put(static_cast<char>(k));
      out << bytes;
      in.close();
      fs::remove(written);
    }
  }
  std::printf("fuzz seeds written to %s\n", dir.string().c_str());
  return 0;
}
