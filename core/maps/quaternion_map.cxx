#include "maps/quaternion_map.h"
