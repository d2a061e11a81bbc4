#include "sampling/hammersley.h"
