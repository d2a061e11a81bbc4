#pragma once
// The built-in environments sampled into equirectangular images, kept on disk.
//
// An analytic environment (the built-in studio, sun-sky, white) is sampled into an image before
// it is analysed (analyzeEnvironment) or importance-sampled (EnvironmentDistribution::bake):
// renderEquirectRefined at 1024 x 512 with 4 x 4 supersamples, the studio's about 3.5 s of CPU
// on this project's two-core machine, paid again by every process that shows it (each
// `aniso render`, thumbnail and window start). Its content never changes, so the image is kept
// in the cache directory and read back (about 6 MB, a few milliseconds).
#include "core/image/image.h"

#include <string>

namespace aniso
{
class Environment;

// renderEquirectRefined(env, width, height, supersample), read from CACHE_DIRECTORY/env when a
// file of exactly this image is there, else computed and written there (under a temporary name,
// then renamed: a reader never sees a partial file). Only environments whose key starts with
// "builtin:" are kept: a file's image is analysed as it is. The file's identity is the key, the
// size, the supersampling and a fingerprint of the radiance (env at 64 fixed directions), so an
// environment whose radiance changed under the same key is sampled anew. A file that does not
// read back exactly (truncated, damaged: its checksum, a value that is not finite) is replaced;
// an empty CACHE_DIRECTORY or one that cannot be written only costs the sampling. Throws as
// renderEquirectRefined.
Image cachedEquirectRefined(const Environment& env, int width, int height, int supersample,
                            const std::string& cacheDirectory);
// The same with defaultCacheDirectory().
Image cachedEquirectRefined(const Environment& env, int width, int height, int supersample);
} // namespace aniso
