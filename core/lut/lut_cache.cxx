#include "lut/lut_cache.h"
