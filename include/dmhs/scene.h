/* A scene builds one case: geometry, the modules it needs and the diagnostics
 * it registers (diagnostic.h), each with the parameters it measures with. */
#ifndef DMHS_SCENE_H
#define DMHS_SCENE_H
#include <petscsys.h>

struct sim;

typedef struct scene scene;
struct scene {
  const char *name;
  /* Reads the scene's options, sets module defaults and enables modules (modules_enable). */
  PetscErrorCode (*set_from_options)(scene *self, struct sim *s);
  /* Creates domain and particles and registers the diagnostics (diagnostics_add). */
  PetscErrorCode (*build)(scene *self, struct sim *s);
  /* Optional: changes the state after every step, after the modules' post_step and
   * before the diagnostics sample it (the intestine parks the liquid past its weir).
   * It holds no state of its own that a restart would need. Collective. */
  PetscErrorCode (*post_step)(scene *self, struct sim *s);
  PetscErrorCode (*destroy)(scene *self);
  void *data;
};

#endif
