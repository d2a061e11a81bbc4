// Writes the seed corpora of the fuzz harnesses into DIR/<harness>/: small meshes through VTK's
// own PLY and STL writers (ASCII and binary, with and without normals and texture coordinates),
// OFF files, a default session through the session writer, and every declared parameter's
// default spelled as the CLI reads it, and material libraries (.mtl) of every statement the MTL
// reader knows, spelt as the format's specification and its PBR extension write them. For the
// readers of the mesh reader program (fuzz_reader_program.cxx): OBJ through vtkOBJWriter, legacy
// VTK through vtkPolyDataWriter and vtkUnstructuredGridWriter, VTP through vtkXMLPolyDataWriter,
// a .vtm through vtkXMLMultiBlockDataWriter (vtm_fixture.h; its pieces are not kept), .gltf and
// .glb through tinygltf's writer, STEP and IGES through OpenCASCADE's STEPControl_Writer and
// IGESControl_Writer (a box and a cylinder).
// Usage: fuzz_make_seeds DIR
#include "core/image/image.h"
#include "fuzz/vtm_fixture.h"
#include "core/parameters/parameters.h"
#include "scene/SceneModel.h"
#include "scene/Session.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"

#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Writer.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <QJsonDocument>
#include <STEPControl_Writer.hxx>
#include <TopoDS_Shape.hxx>
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <tiny_gltf.h>
#include <vector>
#include <vtkCellArray.h>
#include <vtkOBJWriter.h>
#include <vtkPLYWriter.h>
#include <vtkPolyDataWriter.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSTLWriter.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGridWriter.h>
#include <vtkXMLPolyDataWriter.h>

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

void appendBytes(std::vector<unsigned char>& buffer, const void* data, size_t size)
{
  const auto* bytes = static_cast<const unsigned char*>(data);
  buffer.insert(buffer.end(), bytes, bytes + size);
  while (buffer.size() % 4 != 0)
  {
    buffer.push_back(0); // glTF's accessors align to 4 bytes
  }
}

// A glTF model of MESH's triangles (POSITION, NORMAL, TEXCOORD_0, indices) under a placed node,
// with a metallic-roughness material whose base colour is PNG, an image in a buffer view.
tinygltf::Model gltfModel(vtkPolyData* mesh, const std::vector<unsigned char>& png)
{
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "tinygltf";
  std::vector<float> positions;
  std::vector<float> normals;
  std::vector<float> uvs;
  vtkDataArray* n = mesh->GetPointData()->GetNormals();
  vtkDataArray* t = mesh->GetPointData()->GetTCoords();
  std::vector<double> lo(3, 1e300);
  std::vector<double> hi(3, -1e300);
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    for (int k = 0; k < 3; ++k)
    {
      positions.push_back(static_cast<float>(p[k]));
      lo[k] = std::min(lo[k], double(positions.back()));
      hi[k] = std::max(hi[k], double(positions.back()));
    }
    double v[3] = {0, 0, 1};
    if (n)
    {
      n->GetTuple(i, v);
    }
    normals.insert(normals.end(), {float(v[0]), float(v[1]), float(v[2])});
    double uv[2] = {0, 0};
    if (t)
    {
      t->GetTuple(i, uv);
    }
    uvs.insert(uvs.end(), {float(uv[0]), float(uv[1])});
  }
  std::vector<uint16_t> indices;
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  mesh->GetPolys()->InitTraversal();
  while (mesh->GetPolys()->GetNextCell(count, ids))
  {
    for (vtkIdType k = 1; k + 1 < count; ++k) // fans: the meshes' polygons are convex
    {
      indices.insert(indices.end(), {uint16_t(ids[0]), uint16_t(ids[k]), uint16_t(ids[k + 1])});
    }
  }
  tinygltf::Buffer buffer;
  auto view = [&](const void* data, size_t size, int target)
  {
    tinygltf::BufferView bufferView;
    bufferView.buffer = 0;
    bufferView.byteOffset = buffer.data.size();
    bufferView.byteLength = size;
    bufferView.target = target;
    appendBytes(buffer.data, data, size);
    model.bufferViews.push_back(bufferView);
    return int(model.bufferViews.size() - 1);
  };
  auto accessor = [&](int bufferView, int componentType, size_t count, int type)
  {
    tinygltf::Accessor a;
    a.bufferView = bufferView;
    a.componentType = componentType;
    a.count = count;
    a.type = type;
    model.accessors.push_back(a);
    return int(model.accessors.size() - 1);
  };
  const size_t points = positions.size() / 3;
  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  primitive.attributes["POSITION"] =
      accessor(view(positions.data(), positions.size() * 4, TINYGLTF_TARGET_ARRAY_BUFFER),
               TINYGLTF_COMPONENT_TYPE_FLOAT, points, TINYGLTF_TYPE_VEC3);
  model.accessors.back().minValues = lo;
  model.accessors.back().maxValues = hi;
  primitive.attributes["NORMAL"] =
      accessor(view(normals.data(), normals.size() * 4, TINYGLTF_TARGET_ARRAY_BUFFER),
               TINYGLTF_COMPONENT_TYPE_FLOAT, points, TINYGLTF_TYPE_VEC3);
  primitive.attributes["TEXCOORD_0"] =
      accessor(view(uvs.data(), uvs.size() * 4, TINYGLTF_TARGET_ARRAY_BUFFER),
               TINYGLTF_COMPONENT_TYPE_FLOAT, points, TINYGLTF_TYPE_VEC2);
  primitive.indices =
      accessor(view(indices.data(), indices.size() * 2, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
               TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, indices.size(), TINYGLTF_TYPE_SCALAR);
  primitive.material = 0;
  if (!png.empty())
  {
    tinygltf::Image image;
    image.name = "albedo";
    image.mimeType = "image/png";
    image.bufferView = view(png.data(), png.size(), 0);
    model.images.push_back(image);
    tinygltf::Texture texture;
    texture.source = 0;
    model.textures.push_back(texture);
  }
  model.buffers.push_back(buffer);
  tinygltf::Material material;
  material.name = "brushed";
  material.pbrMetallicRoughness.baseColorFactor = {0.9, 0.8, 0.6, 1.0};
  material.pbrMetallicRoughness.metallicFactor = 1.0;
  material.pbrMetallicRoughness.roughnessFactor = 0.3;
  if (!png.empty())
  {
    material.pbrMetallicRoughness.baseColorTexture.index = 0;
  }
  model.materials.push_back(material);
  tinygltf::Mesh gltfMesh;
  gltfMesh.name = "mesh";
  gltfMesh.primitives.push_back(primitive);
  model.meshes.push_back(gltfMesh);
  tinygltf::Node parent;
  parent.name = "assembly";
  parent.translation = {1.0, 0.0, -2.0};
  parent.children = {1};
  model.nodes.push_back(parent);
  tinygltf::Node child;
  child.name = "part";
  child.mesh = 0;
  child.rotation = {0.0, 0.38268343236509, 0.0, 0.923879532511287};
  child.scale = {2.0, 2.0, 2.0};
  model.nodes.push_back(child);
  tinygltf::Scene scene;
  scene.name = "scene";
  scene.nodes = {0};
  model.scenes.push_back(scene);
  model.defaultScene = 0;
  return model;
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
  for (const char* sub : {"ply", "stl", "off", "obj", "vtk", "vtp", "vtm", "gltf", "glb", "step",
                          "iges", "session", "text_values", "image", "material_library", "mtl",
                          "command_line"})
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
      vtkNew<vtkPolyDataWriter> legacy;
      legacy->SetInputData(mesh);
      binary ? legacy->SetFileTypeToBinary() : legacy->SetFileTypeToASCII();
      legacy->SetFileName((dir / "vtk" / (stem + ".vtk")).string().c_str());
      legacy->Write();
      vtkNew<vtkXMLPolyDataWriter> xml;
      xml->SetInputData(mesh);
      binary ? xml->SetDataModeToAppended() : xml->SetDataModeToAscii();
      xml->SetFileName((dir / "vtp" / (stem + ".vtp")).string().c_str());
      xml->Write();
    }
    // vtkOBJWriter writes positions, normals and texture coordinates (v, vn, vt, f a/b/c).
    vtkNew<vtkOBJWriter> obj;
    obj->SetInputData(mesh);
    obj->SetFileName((dir / "obj" / (std::to_string(index / 2) + ".obj")).string().c_str());
    obj->Write();
  }
  {
    // A binary, uncompressed VTP (base64 inline data) and a legacy unstructured grid (a
    // volume: the reader keeps its outer surface).
    vtkNew<vtkXMLPolyDataWriter> xml;
    xml->SetInputData(plate);
    xml->SetDataModeToBinary();
    xml->SetCompressorTypeToNone();
    xml->SetFileName((dir / "vtp" / "inline.vtp").string().c_str());
    xml->Write();
    vtkSmartPointer<vtkMultiBlockDataSet> tree = aniso::fuzz::makeVtmFixture();
    vtkDataObject* grid = vtkMultiBlockDataSet::SafeDownCast(tree->GetBlock(1))->GetBlock(0);
    vtkNew<vtkUnstructuredGridWriter> legacy;
    legacy->SetInputData(grid);
    legacy->SetFileName((dir / "vtk" / "grid.vtk").string().c_str());
    legacy->Write();
  }
  {
    // The .vtm as vtkXMLMultiBlockDataWriter writes it; fuzz_vtm writes the same pieces beside
    // its inputs, so only the .vtm is a seed.
    const fs::path scratch = dir / "vtm" / "scratch";
    fs::create_directories(scratch);
    if (aniso::fuzz::writeVtmFixture(scratch.string(), true))
    {
      const std::string stem = aniso::fuzz::kVtmFixtureStem;
      fs::copy_file(scratch / (stem + ".vtm"), dir / "vtm" / (stem + ".vtm"));
    }
    fs::remove_all(scratch);
  }
  {
    // glTF through tinygltf's writer: the plate with a PNG base colour (OpenImageIO's PNG
    // writer) as .gltf (buffers as data: URIs) and .glb, and the sphere untextured.
    std::vector<unsigned char> png;
    {
      aniso::Image image;
      image.width = 2;
      image.height = 2;
      image.channels = 3;
      image.data = {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
      const fs::path written = dir / "gltf" / "albedo.png";
      aniso::writeImage(written.string(), image);
      std::ifstream in(written, std::ios::binary);
      png.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
      in.close();
      fs::remove(written);
    }
    tinygltf::TinyGLTF writer;
    int k = 0;
    for (const tinygltf::Model& model : {gltfModel(plate, png), gltfModel(sphere, {})})
    {
      std::ofstream text(dir / "gltf" / (std::to_string(k) + ".gltf"), std::ios::binary);
      writer.WriteGltfSceneToStream(&model, text, true, false);
      std::ofstream binary(dir / "glb" / (std::to_string(k) + ".glb"), std::ios::binary);
      writer.WriteGltfSceneToStream(&model, binary, false, true);
      ++k;
    }
  }
  {
    // STEP and IGES through OpenCASCADE's writers: a box (planes) and a cylinder (a periodic
    // surface, seam edges). Their messages (to standard output) are not wanted here.
    Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
    IGESControl_Controller::Init();
    const TopoDS_Shape shapes[] = {BRepPrimAPI_MakeBox(10.0, 20.0, 30.0).Shape(),
                                   BRepPrimAPI_MakeCylinder(5.0, 12.0).Shape()};
    const char* const names[] = {"box", "cylinder"};
    for (int k = 0; k < 2; ++k)
    {
      STEPControl_Writer step;
      step.Transfer(shapes[k], STEPControl_AsIs);
      step.Write((dir / "step" / (std::string(names[k]) + ".step")).string().c_str());
      IGESControl_Writer iges("MM", 0);
      iges.AddShape(shapes[k]);
      iges.ComputeModel();
      iges.Write((dir / "iges" / (std::string(names[k]) + ".iges")).string().c_str());
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
  // Command lines of `aniso render` (arguments separated by NUL bytes): each declared parameter
  // as an option with its default spelt by formatParameterValue, and the README's examples.
  const auto writeCommandLine = [&dir](const std::string& name, const std::vector<std::string>& args)
  {
    std::ofstream out(dir / "command_line" / (name + ".args"), std::ios::binary);
    for (std::size_t i = 0; i < args.size(); ++i)
    {
      if (i > 0)
      {
        out.put('\0');
      }
      out << args[i];
    }
  };
  for (const aniso::ParameterSpec& spec : specs)
  {
    writeCommandLine("option-" + std::string(spec.name),
                     {"--builtin", "sphere", "--" + std::string(spec.name),
                      aniso::formatParameterValue(spec, aniso::defaultParameterValue(spec)), "-o",
                      "out.png"});
  }
  const std::vector<std::vector<std::string>> examples = {
      {"--builtin", "sphere", "--nu", "20000", "--nv", "70", "-o", "sphere.png"},
      {"--builtin", "torus", "--model", "ward", "--light", "dir:0,-1,1:3", "-o", "ward.png"},
      {"--builtin", "plate", "--tpr", "circular", "--view", "+z", "--time", "-o", "disc.png"},
      {"--builtin", "sphere", "--part", "*=spun aluminium", "--exposure", "-1", "-o", "a.png"},
      {"--builtin", "disk", "--model", "microstructure", "--structure", "grooves", "--grid", "4",
       "--f0", "0.95,0.93,0.88", "--light", "point:0,0.6,1.5:3", "--size", "384", "-o", "m.png"},
      {"--builtin", "sphere", "--env", "builtin:sunsky", "--env-sampling", "mis", "--azimuth",
       "20", "--elevation", "55", "--ortho", "-o", "s.exr"},
      {"blade.vtp", "--field", "T:magnitude", "--field-target", "roughness", "--field-range",
       "0,1", "--legend", "off", "-o", "f.png"},
      {"--builtin", "sphere", "--reference", "--reference-step", "4", "--size", "64x64", "-o",
       "r.png"}};
  for (std::size_t i = 0; i < examples.size(); ++i)
  {
    writeCommandLine("example-" + std::to_string(i), examples[i]);
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
