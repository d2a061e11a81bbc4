#include "core/formats/vtk_xml_headers.h"

#include "core/error.h"

#include <algorithm>
#include <array>
#include <fstream>
#include <string_view>
#include <vector>

namespace aniso
{
namespace
{
constexpr std::size_t kReadChunk = 1u << 20;

bool isSpace(char c)
{
  return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

// The value of attribute NAME in a tag's text ("<DataArray type=... >"), either quote.
std::optional<std::string> attribute(std::string_view tag, std::string_view name)
{
  std::size_t at = 0;
  while ((at = tag.find(name, at)) != std::string_view::npos)
  {
    const bool startsWord = at > 0 && isSpace(tag[at - 1]);
    std::size_t p = at + name.size();
    at = p;
    if (!startsWord)
    {
      continue;
    }
    while (p < tag.size() && isSpace(tag[p]))
    {
      ++p;
    }
    if (p >= tag.size() || tag[p] != '=')
    {
      continue;
    }
    ++p;
    while (p < tag.size() && isSpace(tag[p]))
    {
      ++p;
    }
    if (p >= tag.size() || (tag[p] != '"' && tag[p] != '\''))
    {
      continue;
    }
    const char quote = tag[p];
    const std::size_t end = tag.find(quote, p + 1);
    if (end == std::string_view::npos)
    {
      return std::nullopt;
    }
    return std::string(tag.substr(p + 1, end - p - 1));
  }
  return std::nullopt;
}

std::optional<std::uint64_t> parseUnsigned(const std::string& text)
{
  if (text.empty() || text.size() > 19)
  {
    return std::nullopt;
  }
  std::uint64_t value = 0;
  for (char c : text)
  {
    if (c < '0' || c > '9')
    {
      return std::nullopt;
    }
    value = value * 10 + static_cast<std::uint64_t>(c - '0');
  }
  return value;
}

// VTK's base64 alphabet (vtkBase64Utilities): '=' decodes as 0 wherever it stands; -1 for a
// character VTK does not decode.
int base64Value(char c)
{
  if (c >= 'A' && c <= 'Z')
  {
    return c - 'A';
  }
  if (c >= 'a' && c <= 'z')
  {
    return c - 'a' + 26;
  }
  if (c >= '0' && c <= '9')
  {
    return c - '0' + 52;
  }
  if (c == '+')
  {
    return 62;
  }
  if (c == '/')
  {
    return 63;
  }
  if (c == '=')
  {
    return 0;
  }
  return -1;
}

// Decodes base64 as VTK 9.1's stream does: quad by quad, each three bytes, or one when its third
// character is '=', two when its fourth is; decoding stops after a quad of fewer than three bytes
// or at a character VTK does not decode ('=' in a quad's first two places decodes as 0, as in
// VTK: a fuzzed header of "vftGdCKk=AQAAAAC" claims 1 950 809 021 blocks, whose sizes VTK
// allocates, 7.8 GB).
std::vector<unsigned char> decodeBase64(std::string_view chars)
{
  std::vector<unsigned char> bytes;
  for (std::size_t q = 0; q + 4 <= chars.size(); q += 4)
  {
    std::array<int, 4> v{};
    for (std::size_t i = 0; i < 4; ++i)
    {
      v[i] = base64Value(chars[q + i]);
      if (v[i] < 0)
      {
        return bytes;
      }
    }
    const unsigned triple = (static_cast<unsigned>(v[0]) << 18) |
                            (static_cast<unsigned>(v[1]) << 12) |
                            (static_cast<unsigned>(v[2]) << 6) | static_cast<unsigned>(v[3]);
    const int count = chars[q + 2] == '=' ? 1 : chars[q + 3] == '=' ? 2 : 3;
    bytes.push_back(static_cast<unsigned char>(triple >> 16));
    if (count > 1)
    {
      bytes.push_back(static_cast<unsigned char>((triple >> 8) & 0xFF));
    }
    if (count > 2)
    {
      bytes.push_back(static_cast<unsigned char>(triple & 0xFF));
    }
    if (count < 3)
    {
      return bytes;
    }
  }
  return bytes;
}

// Where an array's encoded bytes are: a range of the file (appended data) or of the XML text
// (an inline array), raw or base64.
struct ArrayData
{
  bool base64 = false;
  std::string_view inlineChars; // inline: the element's text
  std::uint64_t fileBegin = 0;  // appended: where the array starts in the file
  std::uint64_t fileEnd = 0;    // appended: the file's size
};

class HeaderReader
{
public:
  HeaderReader(std::ifstream& file, const ArrayData& data) : file_(file), data_(data)
  {
  }

  // The first N decoded bytes, or nothing when the data hold fewer or do not decode.
  std::optional<std::vector<unsigned char>> bytes(std::uint64_t n)
  {
    const std::uint64_t units = data_.base64 ? (n + 2) / 3 * 4 : n;
    if (units > encodedSize())
    {
      return std::nullopt;
    }
    std::string encoded;
    if (data_.fileEnd > 0)
    {
      encoded.resize(units);
      file_.clear();
      file_.seekg(static_cast<std::streamoff>(data_.fileBegin));
      if (!file_.read(encoded.data(), static_cast<std::streamsize>(units)))
      {
        return std::nullopt;
      }
    }
    else
    {
      encoded = std::string(data_.inlineChars.substr(0, units));
    }
    if (!data_.base64)
    {
      return std::vector<unsigned char>(encoded.begin(), encoded.end());
    }
    std::vector<unsigned char> decoded = decodeBase64(encoded);
    if (decoded.size() < n)
    {
      return std::nullopt; // VTK's read stops short too, and it refuses the array
    }
    decoded.resize(n);
    return decoded;
  }

  // Decoded bytes the data hold after a header of N bytes (base64: whole quads).
  std::uint64_t bytesAfter(std::uint64_t n) const
  {
    const std::uint64_t units = data_.base64 ? (n + 2) / 3 * 4 : n;
    const std::uint64_t left = encodedSize() > units ? encodedSize() - units : 0;
    return data_.base64 ? left / 4 * 3 : left;
  }

private:
  std::uint64_t encodedSize() const
  {
    return data_.fileEnd > 0 ? data_.fileEnd - data_.fileBegin : data_.inlineChars.size();
  }

  std::ifstream& file_;
  const ArrayData& data_;
};

std::uint64_t word(const std::vector<unsigned char>& bytes, std::size_t index, std::size_t size,
                   bool bigEndian)
{
  std::uint64_t value = 0;
  for (std::size_t b = 0; b < size; ++b)
  {
    const std::size_t at = index * size + (bigEndian ? b : size - 1 - b);
    value = (value << 8) | bytes[at];
  }
  return value;
}

std::optional<std::string> headerProblem(HeaderReader& reader, std::size_t wordSize,
                                         bool bigEndian)
{
  const std::optional<std::vector<unsigned char>> head = reader.bytes(3 * wordSize);
  if (!head)
  {
    return std::nullopt; // VTK refuses a header it cannot read
  }
  const std::uint64_t blocks = word(*head, 0, wordSize, bigEndian);
  const std::uint64_t blockSize = word(*head, 1, wordSize, bigEndian);
  const std::uint64_t lastSize = word(*head, 2, wordSize, bigEndian);
  if (blocks == 0)
  {
    return std::nullopt;
  }
  if (blockSize == 0)
  {
    return "its compression header has " + std::to_string(blocks) + " blocks of 0 bytes";
  }
  if (lastSize > blockSize)
  {
    return "its compression header has a last block of " + std::to_string(lastSize) +
           " bytes, larger than its blocks of " + std::to_string(blockSize);
  }
  const std::uint64_t room = reader.bytesAfter(3 * wordSize);
  if (blocks > room / wordSize)
  {
    return "its compression header claims " + std::to_string(blocks) +
           " blocks, more sizes than the file holds";
  }
  const std::uint64_t headerBytes = (3 + blocks) * wordSize;
  const std::optional<std::vector<unsigned char>> header = reader.bytes(headerBytes);
  if (!header)
  {
    return std::nullopt;
  }
  const std::uint64_t dataBytes = reader.bytesAfter(headerBytes);
  std::uint64_t total = 0;
  for (std::uint64_t i = 0; i < blocks; ++i)
  {
    const std::uint64_t compressed = word(*header, static_cast<std::size_t>(3 + i), wordSize,
                                          bigEndian);
    const std::uint64_t uncompressed = i + 1 == blocks && lastSize != 0 ? lastSize : blockSize;
    if (compressed > dataBytes || total > dataBytes - compressed)
    {
      return "its compression header's block " + std::to_string(i) + " of " +
             std::to_string(compressed) + " bytes runs past the end of the file (" +
             std::to_string(dataBytes) + " bytes of data)";
    }
    total += compressed;
    if (uncompressed > kMaxVtkXmlExpansion * compressed + kVtkXmlBlockSlack)
    {
      return "its compression header's block " + std::to_string(i) + " expands " +
             std::to_string(compressed) + " bytes to " + std::to_string(uncompressed) +
             " (more than " + std::to_string(kMaxVtkXmlExpansion) + " times plus " +
             std::to_string(kVtkXmlBlockSlack) + " bytes)";
    }
  }
  return std::nullopt;
}

// The XML text of the file, up to its appended data; where that data starts, if it has any.
struct XmlPart
{
  std::string text;
  std::optional<std::uint64_t> appendedStart; // the byte after the '_' that opens the data
  std::string appendedEncoding;
  std::uint64_t fileSize = 0;
};

XmlPart readXmlPart(std::ifstream& file, const std::string& path)
{
  XmlPart part;
  file.seekg(0, std::ios::end);
  const std::streamoff size = file.tellg();
  if (size < 0)
  {
    throw errorAbout(path, "cannot read the file");
  }
  part.fileSize = static_cast<std::uint64_t>(size);
  file.seekg(0);
  std::string chunk(kReadChunk, '\0');
  std::size_t searchFrom = 0;
  while (file)
  {
    file.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    part.text.append(chunk.data(), static_cast<std::size_t>(file.gcount()));
    const std::size_t tag = part.text.find("<AppendedData", searchFrom);
    if (tag != std::string::npos)
    {
      const std::size_t close = part.text.find('>', tag);
      const std::size_t underscore =
          close == std::string::npos ? std::string::npos : part.text.find('_', close);
      if (underscore == std::string::npos && file)
      {
        continue; // the data's start is in the next chunk
      }
      if (underscore != std::string::npos)
      {
        part.appendedEncoding =
            attribute(std::string_view(part.text).substr(tag, close - tag), "encoding")
                .value_or("");
        part.appendedStart = underscore + 1;
      }
      part.text.resize(tag);
      return part;
    }
    searchFrom = part.text.size() > 16 ? part.text.size() - 16 : 0;
  }
  return part;
}

// Each element named NAME in the text: its tag's text and, when it has content, that content
// up to the next '<'.
template <typename Visit>
void forEachElement(std::string_view text, std::string_view name, Visit visit)
{
  std::size_t at = 0;
  const std::string open = "<" + std::string(name);
  while ((at = text.find(open, at)) != std::string_view::npos)
  {
    const std::size_t after = at + open.size();
    if (after >= text.size() || !(isSpace(text[after]) || text[after] == '>' ||
                                  text[after] == '/'))
    {
      at = after;
      continue;
    }
    const std::size_t close = text.find('>', after);
    if (close == std::string_view::npos)
    {
      return;
    }
    const std::string_view tag = text.substr(at, close - at);
    std::string_view content;
    if (close > 0 && text[close - 1] != '/')
    {
      const std::size_t end = text.find('<', close + 1);
      content = text.substr(close + 1,
                            (end == std::string_view::npos ? text.size() : end) - close - 1);
    }
    visit(tag, content);
    at = close + 1;
  }
}

std::string_view trimmed(std::string_view s)
{
  while (!s.empty() && isSpace(s.front()))
  {
    s.remove_prefix(1);
  }
  while (!s.empty() && isSpace(s.back()))
  {
    s.remove_suffix(1);
  }
  return s;
}
} // namespace

std::optional<std::string> vtkXmlHeaderProblem(const std::string& path)
{
  std::ifstream file(path, std::ios::binary);
  if (!file)
  {
    throw errorAbout(path, "cannot open the file");
  }
  const XmlPart xml = readXmlPart(file, path);
  std::optional<std::string> compressor;
  std::size_t wordSize = 4;
  bool bigEndian = false;
  bool known = true;
  forEachElement(xml.text, "VTKFile", [&](std::string_view tag, std::string_view) {
    if (compressor)
    {
      return; // the first VTKFile element is the file's
    }
    compressor = attribute(tag, "compressor").value_or("");
    const std::string type = attribute(tag, "header_type").value_or("UInt32");
    wordSize = type == "UInt64" ? 8 : 4;
    known = type == "UInt64" || type == "UInt32";
    bigEndian = attribute(tag, "byte_order").value_or("") == "BigEndian";
  });
  if (!compressor || compressor->empty() || !known)
  {
    return std::nullopt; // no compression headers, or VTK refuses the header type itself
  }
  std::optional<std::string> problem;
  for (const char* element : {"DataArray", "Array"})
  {
    forEachElement(xml.text, element, [&](std::string_view tag, std::string_view content) {
      if (problem)
      {
        return;
      }
      const std::string format = attribute(tag, "format").value_or("");
      ArrayData data;
      std::string where;
      if (format == "appended")
      {
        const std::optional<std::uint64_t> offset =
            parseUnsigned(attribute(tag, "offset").value_or(""));
        if (!xml.appendedStart || !offset || *xml.appendedStart > xml.fileSize ||
            *offset >= xml.fileSize - *xml.appendedStart)
        {
          return; // VTK refuses an array with no appended data to read
        }
        if (xml.appendedEncoding != "raw" && xml.appendedEncoding != "base64")
        {
          return;
        }
        data.base64 = xml.appendedEncoding == "base64";
        data.fileBegin = *xml.appendedStart + *offset;
        data.fileEnd = xml.fileSize;
        where = "appended at offset " + std::to_string(*offset);
      }
      else if (format == "binary")
      {
        data.base64 = true;
        data.inlineChars = trimmed(content);
        where = "inline";
      }
      else
      {
        return;
      }
      HeaderReader reader(file, data);
      if (std::optional<std::string> reason = headerProblem(reader, wordSize, bigEndian))
      {
        problem = "array '" + attribute(tag, "Name").value_or("") + "' (" + where +
                  "): " + *reason;
      }
    });
  }
  return problem;
}

void checkVtkXmlHeaders(const std::string& path)
{
  if (std::optional<std::string> problem = vtkXmlHeaderProblem(path))
  {
    throw errorAbout(path, *problem);
  }
}
} // namespace aniso
