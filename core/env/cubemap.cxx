#include "env/cubemap.h"
