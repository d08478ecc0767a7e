/* Cleaning the output directory before a run writes into it: see outdir.h. */
#include <dirent.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "dmhs/outdir.h"

/* Regular file dir/name removed: 1, else 0. */
static int outdir_unlink(const char *dir, const char *name) {
  char path[4096];
  struct stat st;
  if (snprintf(path, sizeof(path), "%s/%s", dir, name) >= (int)sizeof(path))
    return 0;
  if (lstat(path, &st) || !S_ISREG(st.st_mode))
    return 0;
  return unlink(path) == 0;
}

int outdir_remove_tmp(const char *dir) {
  DIR *d = opendir(dir);
  int n = 0;
  if (!d)
    return 0;
  for (struct dirent *e; (e = readdir(d));) {
    const size_t len = strlen(e->d_name);
    if (len > 4 && !strcmp(e->d_name + len - 4, ".tmp"))
      n += outdir_unlink(dir, e->d_name);
  }
  closedir(d);
  return n;
}

int outdir_remove_snapshots(const char *dir, long first_index) {
  DIR *d = opendir(dir);
  int n = 0;
  if (!d)
    return 0;
  for (struct dirent *e; (e = readdir(d));) {
    long index;
    int end = 0;
    /* exactly snap_<digits>.h5, the names snapshot_name gives */
    if (sscanf(e->d_name, "snap_%ld.h5%n", &index, &end) == 1 && end > 0 && !e->d_name[end] &&
        strspn(e->d_name + 5, "0123456789") == (size_t)end - 8 && index >= first_index)
      n += outdir_unlink(dir, e->d_name);
  }
  closedir(d);
  if (first_index == 0)
    n += outdir_unlink(dir, "particles.xdmf");
  return n;
}
