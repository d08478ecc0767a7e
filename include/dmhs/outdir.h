/* What a run removes from its output directory before writing (the driver before the run,
 * io's restart after reading its checkpoint; the policy is in doc/guide/output.md, "Output
 * directory"):
 *   - every run: stale <name>.tmp files, left by a write that was interrupted
 *     (killed, disk full): they are never complete;
 *   - a fresh run (no -restart): the snapshots snap_NNNNNN.h5 and
 *     particles.xdmf of an earlier run, which would otherwise sit beside and
 *     after the new run's snapshots;
 *   - a restart: the snapshots numbered from the checkpoint's snapshot counter
 *     on, which the interrupted run wrote after its checkpoint.
 * Plain C (also used on the error path); each returns how many files went. */
#ifndef DMHS_IO_OUTDIR_H
#define DMHS_IO_OUTDIR_H

int outdir_remove_tmp(const char *dir);
int outdir_remove_snapshots(const char *dir, long first_index);

#endif
