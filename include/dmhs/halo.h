/* Ghost particles: periodic images (and, across ranks, copies of neighbours'
 * particles). Built after migration; forward updates refresh ghost fields. */
#ifndef DMHS_HALO_H
#define DMHS_HALO_H
#include <petscsys.h>
#include "dmhs/particles.h"
#include "dmhs/domain.h"

typedef struct halo {
  double width;  /* every interaction reach (SPH support, ...) plus skin */
  PetscInt n, n_alloc;
  PetscInt *source;         /* owned row each ghost copies */
  double (*shift)[DMHS_DIM]; /* periodic shift added to the copied position */
} halo;

PetscErrorCode halo_create(halo *h, double width);
PetscErrorCode halo_destroy(halo *h);
/* Drop old ghosts and create new ones for every owned particle within `width` of a
 * periodic boundary; copies all FIELD_GHOST fields. */
PetscErrorCode halo_build(halo *h, const domain *d, particles *ps);
/* Copy the named fields (by FIELD_* flag set, or a field list) from sources to ghosts. */
PetscErrorCode halo_forward(const halo *h, particles *ps, const char *const field_names[],
                            int n_fields);

#endif
