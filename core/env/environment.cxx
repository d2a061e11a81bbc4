#include "env/environment.h"
