/* Scene couette: channel flow started by the upper plate moving at -wall_speed
 * from t = 0 (doc/cases.md), validated against the series solution. Geometry: channel.c. */
#include "dmhs/channel.h"
#include "dmhs/scenes.h"

PetscErrorCode couette_scene_create(scene **out) {
  return channel_scene_create(CHANNEL_COUETTE, out);
}
