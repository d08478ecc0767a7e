/* The field table: one row per per-particle array, saying its name, width,
 * element type and where it goes (migration, ghosts, checkpoint, output). */
#ifndef DMHS_FIELDS_H
#define DMHS_FIELDS_H
#include <stddef.h>
#include <petscsys.h>

typedef enum { FIELD_REAL, FIELD_INT, FIELD_INT64 } field_kind;

enum {
  FIELD_MIGRATE = 1u << 0,    /* moves with an owned particle to its new rank */
  FIELD_GHOST = 1u << 1,      /* copied to ghosts at every ghost build */
  FIELD_CHECKPOINT = 1u << 2, /* saved in checkpoints (exact restart) */
  FIELD_OUTPUT = 1u << 3,     /* written to snapshots */
  FIELD_OPTIONAL = 1u << 4,   /* exists only when enabled (fields_enable) */
  /* changes only at a neighbour build, or with one forced (a type change: agglomeration
   * sets force_rebuild; a parked particle moves past the skin): ghosts keep the copy of
   * their build, and no refresh between builds sends it */
  FIELD_FIXED = 1u << 5
};

typedef struct {
  const char *name;
  int width;       /* components per particle */
  field_kind kind; /* element type */
  size_t offset;   /* offsetof(particles, <pointer member>) */
  unsigned flags;
  const char *unit;
} field_desc;

/* The active rows (always-present ones and enabled optional ones) and their count. */
const field_desc *fields_table(size_t *count);
/* Bytes of one particle's row of a field. */
size_t fields_row_bytes(const field_desc *f);
/* Address of the pointer member a field lives in, inside a particles struct. */
void **fields_member(void *particles_struct, const field_desc *f);
/* An active field by name, or NULL. */
const field_desc *fields_find(const char *name);
/* Makes an optional row exist; before the first particle is added (scenes'
 * and modules' options passes). Enabling twice is harmless. */
PetscErrorCode fields_enable(const char *name);
/* True when the field exists in this run. */
PetscBool fields_enabled(const char *name);
/* Set by particles_reserve once memory is allocated: enabling is then an error. */
void fields_freeze(PetscBool on);
/* Back to the always-present rows (unit tests that build several stores). */
void fields_reset(void);

#endif
