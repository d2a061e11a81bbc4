#pragma once
// FNV-1a over bytes (64 bits) and a 64-bit value as 16 hexadecimal digits: the names and
// checksums of the cache directory's files (LUTs, the glTF reader's images, the built-in
// environments' images). Not cryptographic.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

namespace aniso
{
inline constexpr uint64_t kFnvOffsetBasis = 14695981039346656037ull;

// Continues HASH over SIZE bytes at DATA (start with the offset basis).
inline uint64_t fnv1a(const void* data, std::size_t size, uint64_t hash = kFnvOffsetBasis)
{
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t k = 0; k < size; ++k)
  {
    hash = (hash ^ bytes[k]) * 1099511628211ull;
  }
  return hash;
}

inline std::string hex16(uint64_t value)
{
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
  return text;
}
} // namespace aniso
