/* quantum.c: the coordinator's boundary, pure (quantum.h). */
#include "quantum.h"

#include <stdlib.h>
#include <string.h>

#include "plant_row.h"

typedef struct {
    ls_event ev;
    int member, seq;
} ordered_event;

static int by_time (const void *a, const void *b)
{
    const ordered_event *x = a, *y = b;
    if (x->ev.t != y->ev.t) return x->ev.t < y->ev.t ? -1 : 1;
    if (x->member != y->member) return x->member - y->member;
    return x->seq - y->seq;
}

void ls_world_init (ls_world *w, uint64_t seed, int sample_hz, FILE *trace)
{
    memset (w, 0, sizeof *w);
    plant_init (&w->pl, seed);
    gripper_init (&w->gr);
    w->trace = trace;
    w->sample_hz = sample_hz;
    w->quanta_per_s = LS_QUANTA_PER_S;
    w->expected = w->live = (1u << LS_MEMBERS) - 1;
    if (trace)
        fprintf (trace, "%s\n", plant_row_columns);
}

/* Sample rows due up to time t (the first at time 0). */
static void samples_until (ls_world *w, double t)
{
    if (!w->trace || w->sample_hz <= 0)
        return;
    for (;;) {
        double ts = w->sample_t0 + (double) w->samples / w->sample_hz;
        if (ts > t)
            return;
        plant_advance (&w->pl, ts);
        for (int i = 0; i < PLANT_AXES; i++)
            plant_row_write (w->trace, &w->pl, &w->gr, i);
        w->samples++;
    }
}

static void apply (ls_world *w, const ordered_event *o)
{
    const ls_event *e = &o->ev;
    if (o->member == LS_MAIN || e->axis != o->member)
        return;
    samples_until (w, e->t);
    plant_advance (&w->pl, e->t);
    if (e->kind == LS_EV_DAC) {
        plant_set_code (&w->pl, e->axis, e->value);
        if (w->trace)
            plant_row_write (w->trace, &w->pl, &w->gr, e->axis);
    } else if (e->kind == LS_EV_RUN)
        plant_set_run (&w->pl, e->axis, e->value != 0);
}

static void apply_events (ls_world *w, const ls_up *const ups[], const ls_event *const events[])
{
    int n = 0;
    for (int m = 0; m < LS_MEMBERS; m++)
        if (ups[m]) n += ups[m]->n_events;
    ordered_event *all = malloc ((n ? n : 1) * sizeof *all);
    n = 0;
    for (int m = 0; m < LS_MEMBERS; m++)
        for (uint32_t i = 0; ups[m] && i < ups[m]->n_events; i++) {
            all[n].ev = events[m][i];
            all[n].member = m;
            all[n++].seq = (int) i;
        }
    qsort (all, n, sizeof *all, by_time);
    for (int i = 0; i < n; i++)
        apply (w, &all[i]);
    free (all);
}

static void remember (ls_history *h, link_wire wire, uint64_t k)
{
    if (!wire.sent) return;
    h->word[h->n % LS_HISTORY] = wire.value;
    h->quantum[h->n % LS_HISTORY] = k;
    h->n++;
}

/* 11/23 -> 11/03 words: the value that follows a command word is that command's */
static void latch_command (ls_history *h, link_wire wire)
{
    if (!wire.sent) return;
    int code = (int) wire.value - LS_COMMAND_BASE;
    if (h->pending) {
        h->value[h->pending] = wire.value;
        h->valued |= 1u << h->pending;
        h->pending = 0;
    } else if (code >= 1 && code <= LS_COMMANDS)
        h->pending = code;
}

static void values_json (FILE *f, const ls_history *h)
{
    int first = 1;
    fputc ('{', f);
    for (int c = 1; c <= LS_COMMANDS; c++)
        if (h->valued & (1u << c)) {
            fprintf (f, "%s\"%d\":%u", first ? "" : ",", c, h->value[c]);
            first = 0;
        }
    fputc ('}', f);
}

static void history_json (FILE *f, const ls_history *h)
{
    int first = h->n > LS_HISTORY ? h->n - LS_HISTORY : 0;
    fputc ('[', f);
    for (int i = first; i < h->n; i++)
        fprintf (f, "%s[%llu,%u]", i > first ? "," : "",
                 (unsigned long long) h->quantum[i % LS_HISTORY], h->word[i % LS_HISTORY]);
    fputc (']', f);
}

void ls_world_status (FILE *f, const ls_world *w, uint64_t k)
{
    static const char *const names[LS_MEMBERS] = { "x", "y", "z", "t", "main" };
    fprintf (f, "{\"quantum\":%llu,\"time_s\":%.6f,\"power\":%d,\"seed\":%llu,\"sample\":%d,"
             "\"members\":{", (unsigned long long) k, (double) k / w->quanta_per_s, w->pl.power,
             (unsigned long long) w->pl.seed, w->sample_hz);
    for (int m = 0; m < LS_MEMBERS; m++)
        fprintf (f, "%s\"%s\":\"%s\"", m ? "," : "", names[m],
                 !(w->expected & (1u << m)) ? "absent" : (w->live & (1u << m)) ? "running" : "lost");
    fprintf (f, "},\"axes\":[");
    for (int a = 0; a < PLANT_AXES; a++) {
        const plant_axis *x = &w->pl.ax[a];
        fprintf (f, "%s{\"axis\":\"%c\",\"pos\":%.3f,\"vel\":%.3f,\"dac\":%d,"
                 "\"counter\":%d,\"run\":%d,\"to_11_03\":", a ? "," : "", plant_axis_names[a],
                 x->p, x->v, x->code, (int) (int16_t) plant_counter (&w->pl, a), x->run);
        history_json (f, &w->to_axis[a]);
        fprintf (f, ",\"sent\":");
        values_json (f, &w->to_axis[a]);
        fprintf (f, ",\"to_11_23\":");
        history_json (f, &w->to_main[a]);
        fputc ('}', f);
    }
    fprintf (f, "]}\n");
}

/* One member's SET PLANT settings at the boundary t: 1 applied, 0 refused. */
static int apply_command (ls_world *w, const plant_command *c, double t)
{
    if (plant_command_apply (&w->pl, c) != NULL)
        return 0;
    if (c->kind == PC_SAMPLE) {                  /* the next sample one period after t */
        w->sample_hz = (int) c->value;
        w->sample_t0 = t;
        w->samples = 1;
    }
    return 1;
}

int ls_world_step (ls_world *w, uint64_t k, const ls_up *const ups[LS_MEMBERS],
                   const ls_event *const events[LS_MEMBERS],
                   const plant_command *const commands[LS_MEMBERS], ls_down downs[LS_MEMBERS])
{
    double t_end = (double) k / w->quanta_per_s;
    link_wire none = { 0 };
    uint32_t refused[LS_MEMBERS] = { 0 };
    int applied = 0;
    apply_events (w, ups, events);
    for (int a = 0; a < LS_LINKS; a++) {
        if (ups[LS_MAIN]) {
            remember (&w->to_axis[a], ups[LS_MAIN]->links[a], k);
            latch_command (&w->to_axis[a], ups[LS_MAIN]->links[a]);
        }
        if (ups[a]) remember (&w->to_main[a], ups[a]->links[0], k);
    }
    samples_until (w, t_end);
    plant_advance (&w->pl, t_end);
    for (int m = 0; m < LS_MEMBERS; m++)
        for (uint32_t i = 0; ups[m] && commands[m] && i < ups[m]->n_commands; i++) {
            int ok = apply_command (w, &commands[m][i], t_end);
            applied += ok;
            refused[m] += !ok;
        }
    for (int m = 0; m < LS_MEMBERS; m++) {
        ls_down *d = &downs[m];
        memset (d, 0, sizeof *d);
        d->quantum = k;
        d->pl = w->pl;
        d->refused = refused[m];
        d->sample_hz = (uint32_t) w->sample_hz;
        if (m == LS_MAIN) {
            d->lost = w->expected & ~w->live & ((1u << LS_LINKS) - 1);
            for (int a = 0; a < LS_LINKS; a++)
                d->links[a] = ups[a] ? ups[a]->links[0] : none;
        } else {
            d->links[0] = ups[LS_MAIN] ? ups[LS_MAIN]->links[m] : none;
            if (!(w->live & (1u << LS_MAIN)))
                d->flags |= LS_END;
        }
    }
    return applied;
}
