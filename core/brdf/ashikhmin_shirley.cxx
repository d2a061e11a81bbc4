#include "brdf/ashikhmin_shirley.h"
