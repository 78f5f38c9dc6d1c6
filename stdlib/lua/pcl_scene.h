/* pcl_scene, the camera's 3-D scene, is declared in pcl_draw.h; kept for its includers. */
#include "pcl_draw.h"
