/* Options files that include others (options_files.h): a nested relative
 * `-options_file Y` missing from the working directory is looked for from the
 * including file's directory upwards, and a file with such an include is handed
 * to PETSc as command-line words in its place. Runs before MPI and PETSc: plain
 * C, every process reads the files itself (as PETSc does for nested includes). */
#include <ctype.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>
#include "dmhs/options_files.h"

#define OF_MAX_DEPTH 16 /* deeper includes (a cycle) are left to PETSc */

typedef struct {
  char **w;
  int n, cap;
} of_words;

typedef struct {
  char *name, *includer, *dirs; /* the include as written, who includes it, where it was sought */
  int line;
} of_missing;

static of_words of_owned; /* every string allocated here, freed by options_files_free */
static char **of_argv;
static of_missing *of_miss;
static int of_n_miss, of_cap_miss;

/* Appends a word (not copied). 0, or -1 when out of memory (a NULL word: a failed copy). */
static int of_push(of_words *ws, char *w) {
  if (!w)
    return -1;
  if (ws->n + 1 >= ws->cap) { /* room for a terminating NULL too */
    char **grown = realloc(ws->w, (size_t)(2 * ws->cap + 16) * sizeof(char *));
    if (!grown)
      return -1;
    ws->w = grown;
    ws->cap = 2 * ws->cap + 16;
  }
  ws->w[ws->n++] = w;
  ws->w[ws->n] = NULL;
  return 0;
}

/* A copy kept until options_files_free, or NULL when out of memory. */
static char *of_strdup(const char *s) {
  char *c = strdup(s);
  if (c && of_push(&of_owned, c)) {
    free(c);
    return NULL;
  }
  return c;
}

/* PetscOptionsValidKey's rule (PETSc is not initialised yet): "-" or "--", then a letter,
 * and not a number such as -inf. */
static int of_is_key(const char *w) {
  char *end;
  if (!w || w[0] != '-')
    return 0;
  if (w[1] == '-')
    w++;
  if (!isalpha((unsigned char)w[1]))
    return 0;
  (void)strtod(w, &end);
  return end == w || *end == '_' || isalnum((unsigned char)*end);
}

static int of_readable(const char *path) {
  struct stat st;
  return stat(path, &st) == 0 && S_ISREG(st.st_mode) && access(path, R_OK) == 0;
}

/* The path to open for the include `name` of file `includer`: as written when it is absolute,
 * exists from the working directory or names a PETSc variable (${...}); else the first of
 * <dir>/name from the includer's directory upwards (*moved = 1). NULL when found nowhere. */
static char *of_resolve(const char *name, const char *includer, int *moved) {
  char dir[PATH_MAX], cand[2 * PATH_MAX];
  *moved = 0;
  if (strchr(name, '$') || of_readable(name))
    return of_strdup(name);
  if (name[0] == '/' || !realpath(includer, dir))
    return NULL;
  for (;;) {
    char *slash = strrchr(dir, '/');
    if (!slash)
      return NULL;
    *slash = 0; /* the including file's directory, then each one above it */
    snprintf(cand, sizeof(cand), "%s/%s", dir, name);
    if (of_readable(cand)) {
      *moved = 1;
      return of_strdup(cand);
    }
    if (!dir[0])
      return NULL;
  }
}

static void of_record_missing(const char *name, const char *includer, int line) {
  char cwd[PATH_MAX], dir[PATH_MAX], dirs[3 * PATH_MAX];
  if (of_n_miss == of_cap_miss) {
    of_missing *grown = realloc(of_miss, (size_t)(2 * of_cap_miss + 4) * sizeof(*grown));
    if (!grown)
      return;
    of_miss = grown;
    of_cap_miss = 2 * of_cap_miss + 4;
  }
  if (!getcwd(cwd, sizeof(cwd)))
    snprintf(cwd, sizeof(cwd), ".");
  if (realpath(includer, dir)) {
    char *slash = strrchr(dir, '/');
    if (slash)
      *slash = 0;
  } else
    snprintf(dir, sizeof(dir), "?");
  snprintf(dirs, sizeof(dirs), "%s, nor from %s upwards", cwd, dir[0] ? dir : "/");
  of_missing *m = &of_miss[of_n_miss];
  m->name = of_strdup(name);
  m->includer = of_strdup(includer);
  m->dirs = of_strdup(dirs);
  m->line = line;
  if (m->name && m->includer && m->dirs)
    of_n_miss++;
}

/* One line of an options file as PETSc's reader splits it: the text before '#', words
 * between blanks. Returns the number of words (up to 3 kept). */
static int of_split(char *text, char *word[3]) {
  int n = 0;
  char *hash = strchr(text, '#');
  if (hash)
    *hash = 0;
  for (char *tok = strtok(text, " \t\r\n"); tok; tok = strtok(NULL, " \t\r\n"), n++)
    if (n < 3)
      word[n] = tok;
  return n;
}

/* The words that stand for `-options_file path` (path opened from the working directory):
 * *needed = 1 when an include inside had to be resolved (the caller must use the words),
 * else the caller keeps `-options_file path` for PETSc. Missing includes are recorded on the
 * way. 0, or -1 when out of memory. */
static int of_expand(const char *path, int depth, of_words *out, int *needed) {
  char *line = NULL;
  size_t cap = 0;
  int number = 0, plain = 1, err = 0;
  *needed = 0;
  if (depth > OF_MAX_DEPTH || strchr(path, '$'))
    return 0;
  FILE *f = fopen(path, "r");
  if (!f)
    return 0; /* PETSc says so, naming it */
  /* YAML (PETSc's own reader decides by the name or the first bytes) */
  const size_t len = strlen(path);
  char head[8] = "";
  if (!fgets(head, sizeof(head), f) || !strncmp(head, "%YAML ", 6) || !strncmp(head, "---", 3) ||
      (len > 5 && !strcmp(path + len - 5, ".yaml")) ||
      (len > 4 && !strcmp(path + len - 4, ".yml")) || (len > 5 && !strcmp(path + len - 5, ".json")))
    plain = 0;
  rewind(f);
  while (!err && getline(&line, &cap, f) >= 0) {
    char *word[3] = {NULL, NULL, NULL};
    number++;
    if (strchr(line, '"'))
      plain = 0; /* PETSc's quoting */
    const int n = of_split(line, word);
    if (!n)
      continue;
    /* what PETSc would refuse or read differently stays with it */
    if (!of_is_key(word[0]) || n > 2 || (n == 2 && of_is_key(word[1]))) {
      plain = 0;
      continue;
    }
    if (strcasecmp(word[0], "-options_file")) {
      err = of_push(out, of_strdup(word[0])) || (n == 2 && of_push(out, of_strdup(word[1])));
      continue;
    }
    if (n < 2) {
      plain = 0;
      continue;
    }
    int moved, inner;
    char *found = of_resolve(word[1], path, &moved);
    if (!found) {
      of_record_missing(word[1], path, number);
      err = of_push(out, of_strdup(word[0])) || of_push(out, of_strdup(word[1]));
      continue;
    }
    of_words sub = {NULL, 0, 0};
    err = of_expand(found, depth + 1, &sub, &inner);
    if (!err && inner) /* the included file's own words, in its place */
      for (int k = 0; k < sub.n && !err; k++)
        err = of_push(out, sub.w[k]);
    else if (!err)
      err = of_push(out, of_strdup(word[0])) || of_push(out, found);
    free(sub.w);
    *needed = *needed || moved || inner;
  }
  free(line);
  fclose(f);
  if (!plain)
    *needed = 0;
  return err ? -1 : 0;
}

int options_files_resolve(int *argc, char ***argv) {
  of_words line = {NULL, 0, 0};
  int changed = 0, err = 0;
  for (int k = 0; k < *argc && !err; k++) {
    const char *w = (*argv)[k];
    if (!strcasecmp(w, "-options_file") && k + 1 < *argc && (*argv)[k + 1][0] != '-') {
      of_words sub = {NULL, 0, 0};
      int needed;
      err = of_expand((*argv)[k + 1], 0, &sub, &needed);
      if (!err && needed) {
        for (int j = 0; j < sub.n && !err; j++)
          err = of_push(&line, sub.w[j]);
        changed = 1;
        k++;
      } else if (!err)
        err = of_push(&line, (*argv)[k]);
      free(sub.w);
    } else
      err = of_push(&line, (*argv)[k]);
  }
  if (err || !changed) {
    free(line.w);
    return err ? -1 : 0;
  }
  of_argv = line.w;
  *argc = line.n;
  *argv = of_argv;
  return 0;
}

void options_files_explain(const char *message, char *out, size_t len) {
  static const char prefix[] = "Unable to open options file ";
  snprintf(out, len, "%s", message ? message : "");
  if (!message || strncmp(message, prefix, sizeof(prefix) - 1))
    return;
  const char *name = message + sizeof(prefix) - 1;
  for (int k = 0; k < of_n_miss; k++)
    if (!strcmp(of_miss[k].name, name)) {
      snprintf(out, len, "%s (included by %s line %d; not found from the working directory %s)",
               message, of_miss[k].includer, of_miss[k].line, of_miss[k].dirs);
      return;
    }
}

void options_files_free(void) {
  for (int k = 0; k < of_owned.n; k++)
    free(of_owned.w[k]);
  free(of_owned.w);
  free(of_argv);
  free(of_miss);
  of_owned = (of_words){NULL, 0, 0};
  of_argv = NULL;
  of_miss = NULL;
  of_n_miss = of_cap_miss = 0;
}
