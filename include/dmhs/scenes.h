/* Constructors of the scenes the registry knows. */
#ifndef DMHS_SCENES_H
#define DMHS_SCENES_H
#include "dmhs/scene.h"

PetscErrorCode poiseuille_scene_create(scene **out);          /* scenes/poiseuille.c */
PetscErrorCode couette_scene_create(scene **out);             /* scenes/couette.c */
PetscErrorCode box_scene_create(scene **out);                 /* scenes/box.c */
PetscErrorCode cantilever_scene_create(scene **out);          /* scenes/cantilever.c */
PetscErrorCode flap_scene_create(scene **out);                /* scenes/flap.c */
PetscErrorCode intestine_scene_create(scene **out);           /* scenes/intestine.c */
PetscErrorCode vein_scene_create(scene **out);                /* scenes/vein.c */
PetscErrorCode peristaltic_channel_scene_create(scene **out); /* scenes/peristaltic_channel.c */

#endif
