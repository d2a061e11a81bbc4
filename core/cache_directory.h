#pragma once
// Where the project keeps what it can bake again (LUTs, the glTF reader's images).
#include <string>

namespace aniso
{
// The project's cache directory: $XDG_CACHE_HOME/aniso if XDG_CACHE_HOME is an absolute path,
// else $HOME/.cache/aniso, else empty (no cache on disk). The LUT cache keeps its files there;
// so do the glTF reader's images (under "gltf/") and the built-in environments' sampled images
// (under "env/", core/env/equirect_cache.h). Not created here.
std::string defaultCacheDirectory();
} // namespace aniso
