/* The plane channel shared by the poiseuille and couette scenes: liquid
 * between walls at y = 0 and y = l, periodic in x. */
#ifndef DMHS_CHANNEL_H
#define DMHS_CHANNEL_H
#include "dmhs/scene.h"

typedef enum { CHANNEL_POISEUILLE, CHANNEL_COUETTE } channel_flow;
PetscErrorCode channel_scene_create(channel_flow flow, scene **out);

#endif
