#pragma once
// Where the project keeps what it can bake again (LUTs, the glTF reader's images).
#include <string>

namespace aniso
{
// The project's cache directory: $XDG_CACHE_HOME/aniso if XDG_CACHE_HOME is an absolute path,
// else $HOME/.cache/aniso, else empty (no cache on disk). The LUT cache keeps its files there;
// so do the glTF reader's images (under "gltf/"). Not created here.
std::string defaultCacheDirectory();
} // namespace aniso
