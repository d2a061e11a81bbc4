#include "reference/reference_integrator.h"
