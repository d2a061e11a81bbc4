// The compression headers of VTK XML files (core/formats/vtk_xml_headers.h), against files VTK's
// own writers make: every layout vtkXMLPolyDataWriter writes (appended raw, appended base64,
// inline binary; UInt32 and UInt64 headers; little and big endian; zlib, LZ4 and LZMA; one block
// and many) passes the check and loads. The same files with one header word changed (patched
// through VTK's own base64 codec where the data are base64) are refused with the reason, by
// loadMesh with the file's name, where VTK 9.1's reader divided by zero (a block size of 0) or
// allocated what the header claimed. A multiblock file with such a piece is refused naming it.
#include "core/error.h"
#include "core/formats/vtk_xml_headers.h"
#include "tests/vtkpasses/mesh/mesh_test_files.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"
#include "vtkpasses/mesh/MeshLoader.h"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>
#include <optional>
#include <string>
#include <vector>
#include <vtkBase64Utilities.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkXMLMultiBlockDataWriter.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLWriter.h>

namespace aniso
{
namespace
{
enum class Layout
{
  AppendedRaw,
  AppendedBase64,
  Inline
};

struct Variant
{
  Layout layout;
  bool wide;      // UInt64 header words
  bool bigEndian; // byte_order="BigEndian"
  int compressor; // vtkXMLWriter::ZLIB, LZ4, LZMA
  int blockSize;  // bytes before compression, per block
};

std::string describe(const Variant& v)
{
  const char* layouts[] = {"appended raw", "appended base64", "inline binary"};
  return std::string(layouts[static_cast<int>(v.layout)]) + (v.wide ? ", UInt64" : ", UInt32") +
         (v.bigEndian ? ", big endian" : ", little endian") + ", compressor " +
         std::to_string(v.compressor) + ", blocks of " + std::to_string(v.blockSize);
}

class VtkXmlHeadersTest : public test::MeshFilesTest
{
protected:
  std::string writeSphere(const std::string& name, const Variant& v) const
  {
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetInputData(makeSphere(48, 24));
    writer->SetFileName(this->path(name).c_str());
    writer->SetDataMode(v.layout == Layout::Inline ? vtkXMLWriter::Binary
                                                   : vtkXMLWriter::Appended);
    writer->SetEncodeAppendedData(v.layout == Layout::AppendedBase64 ? 1 : 0);
    writer->SetHeaderTypeToUInt32();
    if (v.wide)
    {
      writer->SetHeaderTypeToUInt64();
    }
    writer->SetByteOrder(v.bigEndian ? vtkXMLWriter::BigEndian : vtkXMLWriter::LittleEndian);
    writer->SetCompressorType(v.compressor);
    // The headers' layout does not depend on the level, their time does: each block of 512 bytes
    // is one LZMA encoder, whose match finder takes 3 MB at level 0 and 94 MB at the default 5,
    // and AddressSanitizer maps every one afresh (its 72 files: 323 s at level 5, 30 s at 0 under
    // scripts/sanitize.sh); without it level 3 is the quickest here (1.4 s; 3.4 s at 5, 6.9 s
    // at 0, glibc keeping some sizes and mapping others).
#if defined(__SANITIZE_ADDRESS__)
    writer->SetCompressionLevel(0);
#else
    writer->SetCompressionLevel(3);
#endif
    writer->SetBlockSize(static_cast<size_t>(v.blockSize));
    EXPECT_EQ(writer->Write(), 1) << describe(v);
    return this->path(name);
  }
};

std::vector<Variant> allVariants()
{
  std::vector<Variant> variants;
  for (Layout layout : {Layout::AppendedRaw, Layout::AppendedBase64, Layout::Inline})
  {
    for (bool wide : {false, true})
    {
      for (bool big : {false, true})
      {
        for (int compressor : {vtkXMLWriter::ZLIB, vtkXMLWriter::LZ4, vtkXMLWriter::LZMA})
        {
          for (int blockSize : {32768, 512})
          {
            variants.push_back({layout, wide, big, compressor, blockSize});
          }
        }
      }
    }
  }
  return variants;
}

std::string readAll(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void writeAll(const std::string& path, const std::string& content)
{
  std::ofstream(path, std::ios::binary | std::ios::trunc) << content;
}

// Where the first array's header starts in the file: its first byte (raw) or character (base64).
std::size_t firstHeaderAt(const std::string& file, Layout layout)
{
  if (layout == Layout::Inline)
  {
    const std::size_t array = file.find("format=\"binary\"");
    std::size_t at = file.find('>', array) + 1;
    while (file[at] == ' ' || file[at] == '\n')
    {
      ++at;
    }
    return at;
  }
  const std::size_t appended = file.find("<AppendedData");
  return file.find('_', appended) + 1; // the first array's offset is 0
}

// Sets header word INDEX of the file's first array to VALUE, in the file's word size and byte
// order, through VTK's base64 codec where the data are base64.
void patchWord(std::string& file, const Variant& v, std::size_t index, std::uint64_t value)
{
  const std::size_t size = v.wide ? 8 : 4;
  const std::size_t at = firstHeaderAt(file, v.layout);
  std::vector<unsigned char> bytes;
  const std::size_t needed = (index + 1) * size;
  const std::size_t quads = (needed + 2) / 3;
  if (v.layout == Layout::AppendedRaw)
  {
    bytes.assign(file.begin() + static_cast<std::ptrdiff_t>(at),
                 file.begin() + static_cast<std::ptrdiff_t>(at + needed));
  }
  else
  {
    bytes.resize(quads * 3);
    const size_t decoded = vtkBase64Utilities::DecodeSafely(
        reinterpret_cast<const unsigned char*>(file.data() + at), quads * 4, bytes.data(),
        bytes.size());
    ASSERT_EQ(decoded, quads * 3);
  }
  for (std::size_t b = 0; b < size; ++b)
  {
    const std::size_t shift = 8 * (v.bigEndian ? size - 1 - b : b);
    bytes[index * size + b] = static_cast<unsigned char>((value >> shift) & 0xFF);
  }
  if (v.layout == Layout::AppendedRaw)
  {
    std::copy(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(needed),
              file.begin() + static_cast<std::ptrdiff_t>(at));
    return;
  }
  std::vector<unsigned char> chars(quads * 4 + 4);
  const unsigned long written =
      vtkBase64Utilities::Encode(bytes.data(), bytes.size(), chars.data(), 0);
  ASSERT_EQ(written, quads * 4);
  std::copy(chars.begin(), chars.begin() + static_cast<std::ptrdiff_t>(written),
            file.begin() + static_cast<std::ptrdiff_t>(at));
}

TEST_F(VtkXmlHeadersTest, EveryLayoutVtkWritesPassesAndLoads)
{
  int checked = 0;
  for (const Variant& v : allVariants())
  {
    const std::string file = this->writeSphere("sphere.vtp", v);
    EXPECT_EQ(vtkXmlHeaderProblem(file), std::nullopt) << describe(v);
    ++checked;
  }
  EXPECT_EQ(checked, 72);
  // Loaded as the application loads it, for one of each layout.
  for (Layout layout : {Layout::AppendedRaw, Layout::AppendedBase64, Layout::Inline})
  {
    const Variant v{layout, true, true, vtkXMLWriter::ZLIB, 512};
    const std::string file = this->writeSphere("loaded.vtp", v);
    const LoadedMesh mesh = loadMesh(file);
    EXPECT_EQ(mesh.polyData->GetNumberOfPoints(), makeSphere(48, 24)->GetNumberOfPoints())
        << describe(v);
  }
}

struct Corruption
{
  std::size_t word;
  std::uint64_t value;
  const char* reason;
};

TEST_F(VtkXmlHeadersTest, CorruptHeadersAreRefusedWithTheReason)
{
  const std::vector<Corruption> corruptions = {
      {1, 0, "blocks of 0 bytes"},
      {0, 0x7FFFFFF0u, "more sizes than the file holds"},
      {3, 0x7FFFFFF0u, "runs past the end of the file"},
      {1, 0x7FFFFFF0u, "expands"},
      {2, 0x7FFFFFF0u, "a last block of"},
  };
  int refused = 0;
  for (const Variant& v : allVariants())
  {
    if (v.compressor != vtkXMLWriter::ZLIB || v.blockSize != 512)
    {
      continue; // the header's layout is the compressor's and the block size's alike
    }
    const std::string file = this->writeSphere("sphere.vtp", v);
    const std::string sound = readAll(file);
    for (const Corruption& c : corruptions)
    {
      std::string content = sound;
      patchWord(content, v, c.word, c.value);
      ASSERT_NE(content, sound);
      writeAll(file, content);
      const std::optional<std::string> problem = vtkXmlHeaderProblem(file);
      ASSERT_TRUE(problem.has_value()) << describe(v) << ": " << c.reason;
      EXPECT_NE(problem->find(c.reason), std::string::npos) << *problem;
      EXPECT_NE(problem->find("array '"), std::string::npos) << *problem;
      ++refused;
    }
  }
  EXPECT_EQ(refused, 12 * 5);
}

// loadMesh refuses what VTK's reader crashed on (SIGFPE: blocks of 0 bytes) or allocated for,
// with the file's name and the reason, not as a crash of the reader program.
TEST_F(VtkXmlHeadersTest, LoadMeshRefusesTheFileByName)
{
  const Variant v{Layout::AppendedRaw, false, false, vtkXMLWriter::ZLIB, 512};
  for (const Corruption& c : {Corruption{1, 0, "blocks of 0 bytes"},
                              Corruption{3, 0xFFFFFFF0u, "runs past the end of the file"}})
  {
    const std::string file = this->writeSphere("corrupt.vtp", v);
    std::string content = readAll(file);
    patchWord(content, v, c.word, c.value);
    writeAll(file, content);
    try
    {
      loadMesh(file);
      ADD_FAILURE() << "read, though its header is corrupt: " << c.reason;
    }
    catch (const Error& e)
    {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(file + ": ", 0), 0u) << what;
      EXPECT_NE(what.find(c.reason), std::string::npos) << what;
      EXPECT_EQ(what.find("crashed"), std::string::npos) << what;
    }
  }
}

TEST_F(VtkXmlHeadersTest, MultiblockPieceWithACorruptHeaderIsNamed)
{
  vtkNew<vtkMultiBlockDataSet> tree;
  tree->SetNumberOfBlocks(2);
  tree->SetBlock(0, makeSphere(32, 16));
  tree->SetBlock(1, makeTorus(32, 16));
  vtkNew<vtkXMLMultiBlockDataWriter> writer;
  writer->SetInputData(tree);
  writer->SetFileName(this->path("tree.vtm").c_str());
  writer->SetCompressorTypeToZLib();
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  ASSERT_EQ(writer->Write(), 1);
  EXPECT_EQ(loadMeshBlocks(this->path("tree.vtm")).blocks.size(), 2u);

  const std::string piece = this->path("tree/tree_1.vtp");
  ASSERT_TRUE(std::filesystem::exists(piece));
  std::string content = readAll(piece);
  patchWord(content, {Layout::AppendedRaw, false, false, vtkXMLWriter::ZLIB, 32768}, 1, 0);
  writeAll(piece, content);
  try
  {
    loadMeshBlocks(this->path("tree.vtm"));
    ADD_FAILURE() << "read, though a piece's header is corrupt";
  }
  catch (const Error& e)
  {
    const std::string what = e.what();
    EXPECT_NE(what.find("tree.vtm"), std::string::npos) << what;
    EXPECT_NE(what.find("piece tree/tree_1.vtp"), std::string::npos) << what;
    EXPECT_NE(what.find("blocks of 0 bytes"), std::string::npos) << what;
  }
}
} // namespace
} // namespace aniso
