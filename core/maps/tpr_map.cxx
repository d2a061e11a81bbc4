#include "maps/tpr_map.h"
