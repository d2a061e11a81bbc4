#pragma once
// The compression headers of a VTK XML file's binary arrays (.vtp, .vtu and the pieces of a
// .vtm), checked before VTK reads the file. VTK 9.1's vtkXMLDataParser trusts them: a block
// count past the file makes it allocate that many sizes, a compressed block size past the file
// makes it allocate that many bytes (ReadBlock), an uncompressed block size of 0 makes it divide
// by zero (ReadCompressedData, SIGFPE) and a huge one makes it allocate that much for one block.
//
// A compressed array (the VTKFile element names a compressor) starts with the header
//   [number of blocks, uncompressed block size, uncompressed size of a partial last block (0: the
//   last block is full), compressed size of each block]
// in words of header_type (UInt32, the default, or UInt64) in the file's byte_order, raw or in
// base64 (appended data with encoding="base64", inline arrays of format="binary"). A header is
// refused when:
//   - it has blocks but a block size of 0, or a partial last block larger than a block;
//   - its block sizes or its blocks run past the end of the data the file holds;
//   - a block would expand past kMaxVtkXmlExpansion times its compressed size plus
//     kVtkXmlBlockSlack bytes (zlib's deflate expands at most about 1032 times, LZ4 255 times;
//     LZMA on data of one repeated byte reaches about 7000 times).
// What the check cannot read (an encoding or element it does not know, a header cut short, base64
// it cannot decode) is left to VTK's reader, which refuses such a file with its own message. The
// XML is scanned for its DataArray, VTKFile and AppendedData tags, not parsed: a file VTK cannot
// parse is refused by VTK.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace aniso
{
inline constexpr std::uint64_t kMaxVtkXmlExpansion = 8192;
inline constexpr std::uint64_t kVtkXmlBlockSlack = 4096;

// Why the file's compression headers are refused ("array 'Normals': ..."), or nothing when they
// are sound or none can be read. Throws aniso::Error naming the file when it cannot be opened.
std::optional<std::string> vtkXmlHeaderProblem(const std::string& path);

// Throws aniso::Error "PATH: reason" when vtkXmlHeaderProblem finds one.
void checkVtkXmlHeaders(const std::string& path);
} // namespace aniso
