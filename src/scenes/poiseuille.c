/* Scene poiseuille: channel flow driven by a body force F along x from rest
 * (doc/cases.md), validated against the series solution. Geometry: channel.c. */
#include "dmhs/channel.h"
#include "dmhs/scenes.h"

PetscErrorCode poiseuille_scene_create(scene **out) {
  return channel_scene_create(CHANNEL_POISEUILLE, out);
}
