/* vsh_ply_internal.h - a PLY header as the PLY checker sees it. */
#ifndef VSH_PLY_INTERNAL_H
#define VSH_PLY_INTERNAL_H

#include "vsh_mesh_check_internal.h"

#define PLY_MAX_ELEMENTS 16
#define PLY_MAX_PROPERTIES 256
#define PLY_MAX_NAME 64

enum { PLY_ASCII, PLY_BINARY_LE, PLY_BINARY_BE };
/* What a property means to vtkPLYReader (the rest it skips). */
enum { PLY_ROLE_OTHER, PLY_ROLE_COORD, PLY_ROLE_INDICES, PLY_ROLE_TEXCOORD };

typedef struct ply_type {
  int size;     /* bytes in binary files, 0 for an unknown type */
  int integral; /* 1 for the integer types */
  int is_signed;
} ply_type;

typedef struct ply_property {
  char name[PLY_MAX_NAME];
  int is_list;
  ply_type type;  /* of the value, or of the list items */
  ply_type count; /* of the list length */
  int role;
} ply_property;

typedef struct ply_element {
  char name[PLY_MAX_NAME];
  uint64_t count;
  int property_count;
  ply_property properties[PLY_MAX_PROPERTIES];
  int is_vertex, is_face;
} ply_element;

typedef struct ply_header {
  int format;
  int element_count;
  ply_element elements[PLY_MAX_ELEMENTS];
  uint64_t vertex_count; /* of element "vertex" */
  size_t body;           /* offset of the first body byte */
  size_t lines;          /* header lines, so body line numbers continue from them */
} ply_header;

/* Parses and checks the header; 0 on success. */
int vsh__ply_header(const char *data, size_t size, ply_header *h, char *err, size_t err_size);

#endif
