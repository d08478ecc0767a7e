/* Checked option readers (see dmhs/options.h): validate the option's text in
 * the database, naming the option, the value and what it takes, then let
 * PETSc read it. PETSc's own functions are called as (name)(...) so that the
 * macros of options.h do not apply here. */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include "dmhs/sim.h"
#include "dmhs/options.h"
#include "dmhs/strbuf.h"

/* ---- the values every reader returned -------------------------------------
 * For the restart comparison (exact values) and for -help (the section, the
 * description and the value as shown). */

typedef struct {
  char *name, *value;           /* the value, exact (reals read back to the same double) */
  char *section, *text, *shown; /* -help: PetscOptionsBegin title, description, value shown */
  const char *note;             /* -help: why the option does not apply, or NULL */
  size_t order;                 /* first reading */
  PetscBool given;              /* in the options database (else its reader's default) */
} options_entry;

static options_entry *options_seen;
static size_t options_n_seen, options_cap_seen, options_next_order;
static PetscBool options_frozen; /* -help: the chosen scene's values stay */
static const char *options_note;
/* the options marked run control (options_run_control) */
static char **options_marked;
static size_t options_n_marked, options_cap_marked;

static char *options_dup(const char *v) {
  return strdup(v ? v : "");
}

/* Plain malloc: the table may outlive PETSc's allocator (it is cleared by options_forget). */
static PetscErrorCode options_record(PetscOptionItems *po, const char opt[], const char text[],
                                     const char value[], const char shown[]) {
  PetscBool given = PETSC_FALSE;
  PetscFunctionBeginUser;
  if (po)
    PetscCall(PetscOptionsHasName(po->options, po->prefix, opt, &given));
  for (size_t k = 0; k < options_n_seen; k++)
    if (!strcmp(options_seen[k].name, opt)) {
      if (options_frozen)
        PetscFunctionReturn(0);
      options_seen[k].given = options_seen[k].given || given;
      char *v = options_dup(value), *w = options_dup(shown);
      PetscCheck(v && w, PETSC_COMM_SELF, PETSC_ERR_MEM, "out of memory recording option %s", opt);
      free(options_seen[k].value);
      free(options_seen[k].shown);
      options_seen[k].value = v;
      options_seen[k].shown = w;
      PetscFunctionReturn(0);
    }
  if (options_n_seen == options_cap_seen) {
    const size_t cap = 2 * options_cap_seen + 64;
    options_entry *grown = realloc(options_seen, cap * sizeof(*grown));
    PetscCheck(grown, PETSC_COMM_SELF, PETSC_ERR_MEM, "out of memory recording option %s", opt);
    options_seen = grown;
    options_cap_seen = cap;
  }
  options_entry *e = &options_seen[options_n_seen];
  e->name = options_dup(opt);
  e->value = options_dup(value);
  e->shown = options_dup(shown);
  e->section = options_dup(po && po->title ? po->title : "");
  e->text = options_dup(text);
  e->note = options_note;
  e->order = options_next_order++;
  e->given = given;
  PetscCheck(e->name && e->value && e->shown && e->section && e->text, PETSC_COMM_SELF,
             PETSC_ERR_MEM, "out of memory recording option %s", opt);
  options_n_seen++;
  PetscFunctionReturn(0);
}

/* The shortest text that reads back as the same double: exact, and as a user writes it. */
static void options_format_real(double v, char *num, size_t len) {
  for (int digits = 6; digits <= 17; digits++) {
    snprintf(num, len, "%.*g", digits, v);
    if (strtod(num, NULL) == v)
      break;
  }
}

/* n values; shown: the first n_shown of them */
static PetscErrorCode options_record_real(PetscOptionItems *po, const char opt[], const char text[],
                                          const PetscReal *v, PetscInt n, PetscInt n_shown) {
  char value[1024], shown[1024];
  size_t at = 0;
  PetscFunctionBeginUser;
  value[0] = shown[0] = 0;
  for (PetscInt k = 0, at_shown = 0; k < n && at < sizeof(value); k++) {
    char num[32];
    options_format_real(v[k], num, sizeof(num));
    at += (size_t)snprintf(value + at, sizeof(value) - at, "%s%s", k ? "," : "", num);
    if (k < n_shown && at_shown < (PetscInt)sizeof(shown)) /* shown: 6 digits */
      at_shown +=
          snprintf(shown + at_shown, sizeof(shown) - (size_t)at_shown, "%s%g", k ? "," : "", v[k]);
  }
  PetscCall(options_record(po, opt, text, value, shown));
  PetscFunctionReturn(0);
}

void options_forget(void) {
  for (size_t k = 0; k < options_n_seen; k++) {
    free(options_seen[k].name);
    free(options_seen[k].value);
    free(options_seen[k].section);
    free(options_seen[k].text);
    free(options_seen[k].shown);
  }
  free(options_seen);
  options_seen = NULL;
  options_n_seen = options_cap_seen = 0;
  for (size_t k = 0; k < options_n_marked; k++)
    free(options_marked[k]);
  free(options_marked);
  options_marked = NULL;
  options_n_marked = options_cap_marked = 0;
  options_frozen = PETSC_FALSE;
  options_note = NULL;
}

void options_help_freeze(const char *note) {
  options_frozen = PETSC_TRUE;
  options_note = note;
}

PetscErrorCode options_help_print(MPI_Comm comm) {
  char *done;
  PetscFunctionBeginUser;
  PetscCall(PetscCalloc1(options_n_seen + 1, &done));
  for (size_t k = 0; k < options_n_seen; k++) {
    if (done[k])
      continue;
    const char *section = options_seen[k].section;
    int all_noted = 1;
    for (size_t j = k; j < options_n_seen; j++)
      if (!strcmp(options_seen[j].section, section) && !options_seen[j].note)
        all_noted = 0;
    PetscCall(PetscPrintf(comm, "\n%s%s%s%s:\n", section[0] ? section : "Other options",
                          all_noted ? " (" : "", all_noted ? options_seen[k].note : "",
                          all_noted ? ")" : ""));
    for (size_t j = k; j < options_n_seen; j++) {
      const options_entry *e = &options_seen[j];
      if (done[j] || strcmp(e->section, section))
        continue;
      char head[512];
      snprintf(head, sizeof(head), "%s <%s>", e->name, e->shown);
      PetscCall(PetscPrintf(comm, "  %-30s %s%s%s%s\n", head, e->text,
                            !all_noted && e->note ? " (" : "", !all_noted && e->note ? e->note : "",
                            !all_noted && e->note ? ")" : ""));
      done[j] = 1;
    }
  }
  PetscCall(PetscFree(done));
  PetscFunctionReturn(0);
}

/* Options that may differ between a run and its restart (when and where output goes, how
 * long to run, checks and diagnostics that do not change the state), each marked where it is
 * registered (options_run_control). */

PetscErrorCode options_run_control(const char *name) {
  PetscFunctionBeginUser;
  for (size_t k = 0; k < options_n_marked; k++)
    if (!strcmp(options_marked[k], name))
      PetscFunctionReturn(0);
  if (options_n_marked == options_cap_marked) {
    const size_t cap = options_cap_marked ? 2 * options_cap_marked : 32;
    char **grown = realloc(options_marked, cap * sizeof(*grown));
    PetscCheck(grown, PETSC_COMM_SELF, PETSC_ERR_MEM, "out of memory marking option %s", name);
    options_marked = grown;
    options_cap_marked = cap;
  }
  options_marked[options_n_marked] = options_dup(name);
  PetscCheck(options_marked[options_n_marked], PETSC_COMM_SELF, PETSC_ERR_MEM,
             "out of memory marking option %s", name);
  options_n_marked++;
  PetscFunctionReturn(0);
}

static int options_is_run_control(const char *name) {
  for (size_t k = 0; k < options_n_marked; k++)
    if (!strcmp(name, options_marked[k]))
      return 1;
  return 0;
}

static int options_entry_cmp(const void *a, const void *b) {
  return strcmp((*(const options_entry *const *)a)->name, (*(const options_entry *const *)b)->name);
}

PetscErrorCode options_physics(char **text) {
  size_t len = 1;
  const options_entry **sorted;
  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(options_n_seen + 1, &sorted));
  for (size_t k = 0; k < options_n_seen; k++) {
    sorted[k] = &options_seen[k];
    len += strlen(options_seen[k].name) + strlen(options_seen[k].value) + 2;
  }
  qsort(sorted, options_n_seen, sizeof(*sorted), options_entry_cmp);
  PetscCall(PetscMalloc1(len, text));
  (*text)[0] = 0;
  for (size_t k = 0; k < options_n_seen; k++) {
    if (options_is_run_control(sorted[k]->name))
      continue;
    PetscCall(strbuf_cat(*text, len, sorted[k]->name));
    PetscCall(strbuf_cat(*text, len, " "));
    PetscCall(strbuf_cat(*text, len, sorted[k]->value));
    PetscCall(strbuf_cat(*text, len, "\n"));
  }
  PetscCall(PetscFree(sorted));
  PetscFunctionReturn(0);
}

/* ---- did you mean ----------------------------------------------------------- */

/* Edit distance between a and b, case-insensitive (PETSc's names are): insertions,
 * deletions, substitutions and swaps of two neighbours each count 1; capped at
 * OPTIONS_FAR (names longer than OPTIONS_NAME are far). */
#define OPTIONS_FAR  99
#define OPTIONS_NAME 128
static int options_distance(const char *a, const char *b) {
  int d[OPTIONS_NAME + 1][OPTIONS_NAME + 1];
  const int n = (int)strlen(a), m = (int)strlen(b);
  if (n > OPTIONS_NAME || m > OPTIONS_NAME)
    return OPTIONS_FAR;
  for (int i = 0; i <= n; i++)
    for (int j = 0; j <= m; j++) {
      if (!i || !j) {
        d[i][j] = i + j;
        continue;
      }
      const int ca = tolower((unsigned char)a[i - 1]), cb = tolower((unsigned char)b[j - 1]);
      int v = PetscMin(d[i - 1][j] + 1, d[i][j - 1] + 1);
      v = PetscMin(v, d[i - 1][j - 1] + (ca != cb));
      if (i > 1 && j > 1 && ca == tolower((unsigned char)b[j - 2]) &&
          tolower((unsigned char)a[i - 2]) == cb)
        v = PetscMin(v, d[i - 2][j - 2] + 1);
      d[i][j] = v;
    }
  return d[n][m];
}

/* How close a recorded name is to a name nobody read: its edit distance when small for the
 * name's length (1 up to 7 characters, 2 up to 11, then 3), 4 when one starts the other
 * (-vein_leaf for -vein_leaflet_ka), else OPTIONS_FAR. The same name is not close. */
static int options_closeness(const char *unknown, const char *known) {
  const size_t n = strlen(unknown), m = strlen(known);
  const int d = options_distance(unknown, known), limit = n < 8 ? 1 : n < 12 ? 2 : 3;
  if (d == 0)
    return OPTIONS_FAR;
  if (d <= limit)
    return d;
  if (n >= 5 && m >= 5 && !strncasecmp(unknown, known, PetscMin(n, m)))
    return 4;
  return OPTIONS_FAR;
}

PetscErrorCode options_nearest(const char *name, char *out, size_t len) {
  const char *best[3] = {NULL, NULL, NULL};
  int score[3] = {OPTIONS_FAR, OPTIONS_FAR, OPTIONS_FAR};
  PetscFunctionBeginUser;
  out[0] = 0;
  for (size_t k = 0; k < options_n_seen; k++) {
    const char *known = options_seen[k].name;
    int c = options_closeness(name, known);
    /* the three closest, ties by name: the same text on every rank */
    for (int j = 0; j < 3 && c < OPTIONS_FAR; j++)
      if (c < score[j] || (c == score[j] && best[j] && strcmp(known, best[j]) < 0)) {
        const char *kn = best[j];
        const int kc = score[j];
        best[j] = known;
        score[j] = c;
        known = kn;
        c = kc;
      }
  }
  for (int j = 0; j < 3 && best[j]; j++) {
    if (score[j] > score[0])
      break; /* only the closest */
    const size_t at = strlen(out);
    const PetscBool last = j == 2 || !best[j + 1] || score[j + 1] > score[0];
    snprintf(out + at, len - at, "%s%s", j ? (last ? " or " : ", ") : "", best[j]);
  }
  PetscFunctionReturn(0);
}

/* The value of name in a "name value\n" list, or NULL; *vlen its length. */
static const char *options_lookup(const char *list, const char *name, size_t *vlen) {
  const size_t nlen = strlen(name);
  for (const char *line = list; line && *line;) {
    const char *end = strchr(line, '\n');
    const size_t llen = end ? (size_t)(end - line) : strlen(line);
    if (llen > nlen && !strncmp(line, name, nlen) && line[nlen] == ' ') {
      *vlen = llen - nlen - 1;
      return line + nlen + 1;
    }
    line = end ? end + 1 : NULL;
  }
  return NULL;
}

static void options_append(char *report, size_t len, int *n, const char *name, const char *was,
                           size_t was_len, const char *now, size_t now_len) {
  const size_t at = strlen(report);
  if (at + 1 < len)
    snprintf(report + at, len - at, "%s%s %.*s in the checkpoint, %.*s now", *n ? "; " : "", name,
             (int)was_len, was ? was : "(not set)", (int)now_len, now ? now : "(not set)");
  (*n)++;
}

/* Was the recorded option name in the options database? */
static PetscBool options_given(const char *name) {
  for (size_t k = 0; k < options_n_seen; k++)
    if (!strcmp(options_seen[k].name, name))
      return options_seen[k].given;
  return PETSC_FALSE;
}

PetscErrorCode options_compare_physics(const char *stored, char *report, size_t len, int *n_changed,
                                       char *added, size_t added_len, int *n_added) {
  char *now;
  PetscFunctionBeginUser;
  PetscCall(options_physics(&now));
  report[0] = 0;
  added[0] = 0;
  *n_changed = *n_added = 0;
  for (int pass = 0; pass < 2; pass++) {
    const char *a = pass ? stored : now, *b = pass ? now : stored;
    for (const char *line = a; *line;) {
      const char *end = strchr(line, '\n');
      const size_t llen = end ? (size_t)(end - line) : strlen(line);
      const char *space = memchr(line, ' ', llen);
      if (space) {
        char name[128];
        const size_t nlen = PetscMin((size_t)(space - line), sizeof(name) - 1);
        size_t blen = 0;
        memcpy(name, line, nlen);
        name[nlen] = 0;
        const char *value = space + 1, *other = options_lookup(b, name, &blen);
        const size_t vlen = llen - nlen - 1;
        if (!other && !options_is_run_control(name)) { /* only on one side */
          if (pass)
            options_append(report, len, n_changed, name, value, vlen, NULL, 9);
          else if (!options_given(name)) { /* a reader the writer's dmhs did not have */
            const size_t at = strlen(added);
            if (at + 1 < added_len)
              snprintf(added + at, added_len - at, "%s%s %.*s", *n_added ? "; " : "", name,
                       (int)vlen, value);
            (*n_added)++;
          } else
            options_append(report, len, n_changed, name, NULL, 9, value, vlen);
        } else if (other && !pass && (blen != vlen || strncmp(value, other, vlen)))
          options_append(report, len, n_changed, name, other, blen, value, vlen);
      }
      line = end ? end + 1 : line + llen;
    }
  }
  PetscCall(PetscFree(now));
  PetscFunctionReturn(0);
}

/* The option's text: *found, and *raw = NULL when it was given without a value. */
static PetscErrorCode options_raw(PetscOptions options, const char pre[], const char opt[],
                                  const char **raw, PetscBool *found) {
  PetscFunctionBeginUser;
  *raw = NULL;
  PetscCall(PetscOptionsFindPair(options, pre, opt, raw, found));
  if (*found && *raw && !(*raw)[0])
    *raw = NULL;
  PetscFunctionReturn(0);
}

/* The whole of t (trailing blanks aside) is a number. */
static int options_parse_real(const char *t, double *v) {
  char *end;
  *v = strtod(t, &end);
  if (end == t)
    return 0;
  while (isspace((unsigned char)*end))
    end++;
  return *end == 0;
}

static int options_parse_int(const char *t, long long *v) {
  char *end;
  errno = 0;
  *v = strtoll(t, &end, 10);
  if (end == t || errno == ERANGE)
    return 0;
  while (isspace((unsigned char)*end))
    end++;
  return *end == 0;
}

static PetscErrorCode options_check_real(MPI_Comm comm, const char opt[], const char raw[],
                                         const char elem[], const char takes[], const char text[]) {
  double v;
  char what[300];
  PetscFunctionBeginUser;
  if (elem == raw)
    what[0] = 0;
  else
    snprintf(what, sizeof(what), "'%s' is ", elem);
  PetscCheck(options_parse_real(elem, &v), comm, PETSC_ERR_ARG_WRONG,
             "%s %s: %snot a number; %s takes %s (%s)", opt, raw, what, opt, takes, text);
  PetscCheck(isfinite(v), comm, PETSC_ERR_ARG_OUTOFRANGE, "%s %s: %snot finite; %s takes %s (%s)",
             opt, raw, what, opt, takes, text);
  PetscFunctionReturn(0);
}

static PetscErrorCode options_need_value(MPI_Comm comm, const char opt[], const char *raw,
                                         const char takes[], const char text[]) {
  PetscFunctionBeginUser;
  PetscCheck(raw, comm, PETSC_ERR_ARG_WRONG,
             "option %s was given without a value; it takes %s (%s)", opt, takes, text);
  PetscFunctionReturn(0);
}

/* Comma-separated elements of raw: at most nmax, each checked by kind (0 real, 1 string). */
static PetscErrorCode options_check_list(MPI_Comm comm, const char opt[], const char raw[],
                                         PetscInt nmax, int kind, const char text[]) {
  char takes[96], elem[256];
  PetscInt count = 0;
  PetscFunctionBeginUser;
  snprintf(takes, sizeof(takes), "up to %d %s separated by commas", (int)nmax,
           kind == 0 ? "finite real numbers" : "names");
  for (const char *c = raw;; c++) {
    const char *comma = strchr(c, ',');
    const size_t len = comma ? (size_t)(comma - c) : strlen(c);
    count++;
    PetscCheck(len < sizeof(elem), comm, PETSC_ERR_ARG_WRONG, "%s %s: an element is too long", opt,
               raw);
    memcpy(elem, c, len);
    elem[len] = 0;
    PetscCheck(len > 0, comm, PETSC_ERR_ARG_WRONG, "%s %s: empty element %d; %s takes %s (%s)", opt,
               raw, (int)count, opt, takes, text);
    if (kind == 0)
      PetscCall(options_check_real(comm, opt, raw, elem, takes, text));
    if (!comma)
      break;
    c = comma;
  }
  PetscCheck(count <= nmax, comm, PETSC_ERR_ARG_SIZ, "%s %s: %d values, but %s takes %s (%s)", opt,
             raw, (int)count, opt, takes, text);
  PetscFunctionReturn(0);
}

static PetscErrorCode options_check_int(MPI_Comm comm, const char opt[], const char *raw,
                                        PetscInt lb, PetscInt ub, const char text[]) {
  long long v;
  PetscFunctionBeginUser;
  PetscCall(options_need_value(comm, opt, raw, "an integer", text));
  PetscCheck(options_parse_int(raw, &v), comm, PETSC_ERR_ARG_WRONG,
             "%s %s: not an integer; %s takes an integer (%s)", opt, raw, opt, text);
  PetscCheck(v >= lb && v <= ub, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "%s %s: out of range; %s takes an integer in [%" PetscInt_FMT ", %" PetscInt_FMT
             "] (%s)",
             opt, raw, opt, lb, ub, text);
  PetscFunctionReturn(0);
}

static PetscErrorCode options_check_bool(MPI_Comm comm, const char opt[], const char *raw,
                                         const char text[]) {
  static const char *const words[] = {"1", "0", "true", "false", "yes", "no", "on", "off"};
  PetscFunctionBeginUser;
  if (!raw)
    PetscFunctionReturn(0); /* -quiet alone means true */
  for (size_t k = 0; k < sizeof(words) / sizeof(words[0]); k++)
    if (!strcasecmp(raw, words[k]))
      PetscFunctionReturn(0);
  SETERRQ(comm, PETSC_ERR_ARG_WRONG,
          "%s %s: not a boolean; %s takes true or false (or nothing for true) (%s)", opt, raw, opt,
          text);
}

PetscErrorCode options_real(PetscOptionItems *PetscOptionsObject, const char opt[],
                            const char text[], const char man[], PetscReal current,
                            PetscReal *value, PetscBool *set) {
  const char *raw;
  PetscBool found;
  PetscFunctionBeginUser;
  PetscCall(
      options_raw(PetscOptionsObject->options, PetscOptionsObject->prefix, opt, &raw, &found));
  if (found) {
    PetscCall(options_need_value(PetscOptionsObject->comm, opt, raw, "a finite real number", text));
    PetscCall(
        options_check_real(PetscOptionsObject->comm, opt, raw, raw, "a finite real number", text));
  }
  PetscCall(PetscOptionsReal(opt, text, man, current, value, set));
  PetscCall(options_record_real(PetscOptionsObject, opt, text, value, 1, 1));
  PetscFunctionReturn(0);
}

PetscErrorCode options_int(PetscOptionItems *PetscOptionsObject, const char opt[],
                           const char text[], const char man[], PetscInt current, PetscInt *value,
                           PetscBool *set, PetscInt lb, PetscInt ub) {
  const char *raw;
  PetscBool found;
  PetscFunctionBeginUser;
  PetscCall(
      options_raw(PetscOptionsObject->options, PetscOptionsObject->prefix, opt, &raw, &found));
  if (found)
    PetscCall(options_check_int(PetscOptionsObject->comm, opt, raw, lb, ub, text));
  PetscCall(PetscOptionsRangeInt(opt, text, man, current, value, set, lb, ub));
  {
    char v[32];
    snprintf(v, sizeof(v), "%" PetscInt_FMT, *value);
    PetscCall(options_record(PetscOptionsObject, opt, text, v, v));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode options_bool(PetscOptionItems *PetscOptionsObject, const char opt[],
                            const char text[], const char man[], PetscBool current,
                            PetscBool *value, PetscBool *set) {
  const char *raw;
  PetscBool found;
  PetscFunctionBeginUser;
  PetscCall(
      options_raw(PetscOptionsObject->options, PetscOptionsObject->prefix, opt, &raw, &found));
  if (found)
    PetscCall(options_check_bool(PetscOptionsObject->comm, opt, raw, text));
  PetscCall(PetscOptionsBool(opt, text, man, current, value, set));
  PetscCall(options_record(PetscOptionsObject, opt, text, *value ? "true" : "false",
                           *value ? "true" : "false"));
  PetscFunctionReturn(0);
}

PetscErrorCode options_string(PetscOptionItems *PetscOptionsObject, const char opt[],
                              const char text[], const char man[], const char current[],
                              char *value, size_t len, PetscBool *set) {
  const char *raw;
  PetscBool found;
  PetscFunctionBeginUser;
  PetscCall(
      options_raw(PetscOptionsObject->options, PetscOptionsObject->prefix, opt, &raw, &found));
  if (found) {
    PetscCall(options_need_value(PetscOptionsObject->comm, opt, raw, "a text value", text));
    PetscCheck(strlen(raw) < len, PetscOptionsObject->comm, PETSC_ERR_ARG_SIZ,
               "%s %s: longer than %zu characters", opt, raw, len - 1);
  }
  PetscCall(PetscOptionsString(opt, text, man, current, value, len, set));
  PetscCall(options_record(PetscOptionsObject, opt, text, value, value[0] ? value : "none"));
  PetscFunctionReturn(0);
}

PetscErrorCode options_enum(PetscOptionItems *PetscOptionsObject, const char opt[],
                            const char text[], const char man[], const char *const *list,
                            PetscEnum current, PetscEnum *value, PetscBool *set) {
  const char *raw;
  PetscBool found;
  char choices[256] = "";
  int n = 0;
  PetscFunctionBeginUser;
  while (list[n])
    n++;
  n -= 2; /* PETSc enum lists end with the type name and the prefix */
  for (int k = 0; k < n; k++) {
    if (k)
      PetscCall(strbuf_cat(choices, sizeof(choices), ", "));
    PetscCall(strbuf_cat(choices, sizeof(choices), list[k]));
  }
  PetscCall(
      options_raw(PetscOptionsObject->options, PetscOptionsObject->prefix, opt, &raw, &found));
  if (found) {
    char takes[300];
    snprintf(takes, sizeof(takes), "one of %s", choices);
    PetscCall(options_need_value(PetscOptionsObject->comm, opt, raw, takes, text));
    int k = 0;
    while (k < n && strcasecmp(raw, list[k]))
      k++;
    PetscCheck(k < n, PetscOptionsObject->comm, PETSC_ERR_ARG_UNKNOWN_TYPE,
               "%s %s: unknown value; %s takes %s (%s)", opt, raw, opt, takes, text);
  }
  PetscCall(PetscOptionsEnum(opt, text, man, list, current, value, set));
  {
    const char *v = (int)*value >= 0 && (int)*value < n ? list[*value] : "?";
    char described[600];
    snprintf(described, sizeof(described), "%s; one of %s", text, choices);
    PetscCall(options_record(PetscOptionsObject, opt, described, v, v));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode options_real_array(PetscOptionItems *PetscOptionsObject, const char opt[],
                                  const char text[], const char man[], PetscReal value[],
                                  PetscInt *n, PetscBool *set) {
  const char *raw;
  PetscBool found;
  PetscFunctionBeginUser;
  PetscCall(
      options_raw(PetscOptionsObject->options, PetscOptionsObject->prefix, opt, &raw, &found));
  if (found) {
    char takes[96];
    snprintf(takes, sizeof(takes), "up to %d finite real numbers separated by commas", (int)*n);
    PetscCall(options_need_value(PetscOptionsObject->comm, opt, raw, takes, text));
    PetscCall(options_check_list(PetscOptionsObject->comm, opt, raw, *n, 0, text));
  }
  const PetscInt nmax = *n;
  PetscBool given;
  PetscCall(PetscOptionsRealArray(opt, text, man, value, n, &given));
  if (set)
    *set = given;
  if (!given)
    *n = nmax; /* PETSc says 0 when the option is absent: the defaults stay */
  /* shown: what was given, else the defaults; a list longer than a vector (one value per
   * type, report times) without its unset tail */
  PetscInt n_shown = *n;
  if (!given && nmax > 3) /* zeros or copies of the value before */
    while (n_shown > 1 && (value[n_shown - 1] == 0 || value[n_shown - 1] == value[n_shown - 2]))
      n_shown--;
  PetscCall(options_record_real(PetscOptionsObject, opt, text, value, *n, n_shown));
  if (!given)
    *n = 0;
  PetscFunctionReturn(0);
}

PetscErrorCode options_string_array(PetscOptionItems *PetscOptionsObject, const char opt[],
                                    const char text[], const char man[], char *value[], PetscInt *n,
                                    PetscBool *set) {
  const char *raw;
  PetscBool found;
  char v[1024] = ""; /* the values as recorded, joined by commas */
  PetscFunctionBeginUser;
  PetscCall(
      options_raw(PetscOptionsObject->options, PetscOptionsObject->prefix, opt, &raw, &found));
  if (found) {
    char takes[96];
    snprintf(takes, sizeof(takes), "up to %d names separated by commas", (int)*n);
    PetscCall(options_need_value(PetscOptionsObject->comm, opt, raw, takes, text));
    PetscCall(options_check_list(PetscOptionsObject->comm, opt, raw, *n, 1, text));
    PetscCheck(strlen(raw) < sizeof(v), PetscOptionsObject->comm, PETSC_ERR_ARG_SIZ,
               "%s %s: longer than %zu characters", opt, raw, sizeof(v) - 1);
  }
  PetscBool given;
  PetscCall(PetscOptionsStringArray(opt, text, man, value, n, &given));
  if (set)
    *set = given;
  {
    for (PetscInt k = 0; given && k < *n; k++) {
      if (k)
        PetscCall(strbuf_cat(v, sizeof(v), ","));
      PetscCall(strbuf_cat(v, sizeof(v), value[k]));
    }
    PetscCall(options_record(PetscOptionsObject, opt, text, given ? v : "(default)",
                             given ? v : "default"));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode options_get_real(PetscOptions options, const char pre[], const char opt[],
                                PetscReal *value, PetscBool *set) {
  const char *raw;
  PetscBool found;
  PetscFunctionBeginUser;
  PetscCall(options_raw(options, pre, opt, &raw, &found));
  if (found) {
    PetscCall(options_need_value(PETSC_COMM_SELF, opt, raw, "a finite real number", "see -help"));
    PetscCall(
        options_check_real(PETSC_COMM_SELF, opt, raw, raw, "a finite real number", "see -help"));
  }
  PetscCall(PetscOptionsGetReal(options, pre, opt, value, set));
  PetscFunctionReturn(0);
}

PetscErrorCode options_get_int(PetscOptions options, const char pre[], const char opt[],
                               PetscInt *value, PetscBool *set) {
  const char *raw;
  PetscBool found;
  PetscFunctionBeginUser;
  PetscCall(options_raw(options, pre, opt, &raw, &found));
  if (found)
    PetscCall(
        options_check_int(PETSC_COMM_SELF, opt, raw, PETSC_MIN_INT, PETSC_MAX_INT, "see -help"));
  PetscCall(PetscOptionsGetInt(options, pre, opt, value, set));
  PetscFunctionReturn(0);
}

PetscErrorCode options_get_bool(PetscOptions options, const char pre[], const char opt[],
                                PetscBool *value, PetscBool *set) {
  const char *raw;
  PetscBool found;
  PetscFunctionBeginUser;
  PetscCall(options_raw(options, pre, opt, &raw, &found));
  if (found)
    PetscCall(options_check_bool(PETSC_COMM_SELF, opt, raw, "see -help"));
  PetscCall(PetscOptionsGetBool(options, pre, opt, value, set));
  PetscFunctionReturn(0);
}
