/* A scene builds one case: geometry, the modules it needs and its diagnostics. */
#ifndef DMHS_SCENE_H
#define DMHS_SCENE_H
#include <petscsys.h>

struct sim;
struct checkpoint_io;

typedef struct scene scene;
struct scene {
  const char *name;
  PetscErrorCode (*set_from_options)(scene *self, struct sim *s);
  /* Creates domain, particles and enables modules (modules_enable). */
  PetscErrorCode (*build)(scene *self, struct sim *s);
  /* Called after every completed step (and once before step 1 with step = 0). */
  PetscErrorCode (*diagnose)(scene *self, struct sim *s);
  /* End-of-run report. */
  PetscErrorCode (*finish)(scene *self, struct sim *s);
  PetscErrorCode (*destroy)(scene *self);
  void *data;
  /* Optional: save / restore the scene's diagnostics state (checkpoint.h). */
  PetscErrorCode (*checkpoint_write)(scene *self, struct sim *s, struct checkpoint_io *io);
  PetscErrorCode (*checkpoint_read)(scene *self, struct sim *s, struct checkpoint_io *io);
};

#endif
