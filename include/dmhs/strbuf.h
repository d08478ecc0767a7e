/* Appending to a fixed-size text buffer, in place of PetscStrlcat: PETSc
 * 3.18's bounds the copy by size - strlen(src) rather than by the space left,
 * so it can cut src short while room remains, or write past the buffer.
 * src/core/strbuf.c. */
#ifndef DMHS_STRBUF_H
#define DMHS_STRBUF_H
#include <stddef.h>
#include <petscsys.h>

/* Appends src to the NUL-terminated text in dst, a buffer of size bytes. Never
 * truncates: if the result (with its NUL) does not fit in size bytes, or dst
 * holds no NUL within size, it is PETSC_ERR_ARG_SIZ and dst is left as it was.
 * A NULL src appends nothing (as PetscStrlcat). */
PetscErrorCode strbuf_cat(char *dst, size_t size, const char *src);

#endif
