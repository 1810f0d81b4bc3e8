/* vsh_core.h - everything in vtkshadow_core, the VTK-free, OpenGL-free
 * double-precision shadow math (conventions: see vsh_mat4.h, vsh_camera.h,
 * vsh_planar.h). Include the individual headers where only one is needed. */
#ifndef VSH_CORE_H
#define VSH_CORE_H

#include "vsh_vec3.h"
#include "vsh_mat4.h"
#include "vsh_bounds.h"
#include "vsh_camera.h"
#include "vsh_planar.h"
#include "vsh_csm.h"
#include "vsh_auto.h"
#include "vsh_auto_general.h"
#include "vsh_mesh_topology.h"
#include "vsh_silhouette.h"
#include "vsh_plane.h"
#include "vsh_frustum.h"
#include "vsh_reflect.h"
#include "vsh_soft.h"
#include "vsh_pcss.h"

#endif
