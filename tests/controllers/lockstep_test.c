/* lockstep_test.c: the lock-step's pure logic tested alone: one link end
   (lockstep/link.c) and the coordinator's boundary (lockstep/quantum.c).
   One line per check; exits non-zero if any fails. Built by make as
   build/lockstep_test, run from tests/controllers/test_lockstep_unit.py. */
#define _POSIX_C_SOURCE 200809L   /* open_memstream */
#include "link.h"
#include "quantum.h"
#include "world_status.h"
#include "plant_row.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int failures, checks;

static void check (int ok, const char *what, long got, long want)
{
    checks++;
    if (!ok) failures++;
    printf ("%s %s: got %ld, expected %ld\n", ok ? "ok  " : "FAIL", what, got, want);
}

#define CHECK_EQ(what, got, want) check ((long) (got) == (long) (want), what, (long) (got), (long) (want))

static void link_handshake (void)
{
    link_end a, b;
    memset (&a, 0, sizeof a); memset (&b, 0, sizeof b);
    link_init (&a); link_init (&b);
    link_write_csr (&a, 0177777);
    CHECK_EQ ("CSR keeps only INT ENB A/B and the user bits", link_read_csr (&a), 0000143);
    link_write_csr (&a, 0);
    link_write_outbuf (&a, 012345);
    link_write_outbuf (&a, 054321);
    CHECK_EQ ("nothing crosses before the boundary", link_read_csr (&b) & LINK_REQA, 0);
    link_wire w = link_take_wire (&a);
    CHECK_EQ ("two writes in a quantum: the last crosses", w.value, 054321);
    link_deliver (&b, w);
    CHECK_EQ ("REQ A sets at the boundary", link_read_csr (&b) & LINK_REQA, LINK_REQA);
    CHECK_EQ ("the wire is emptied once taken", link_take_wire (&a).sent, 0);
    link_write_csr (&b, LINK_IEA);
    CHECK_EQ ("INT ENB A with REQ A requests", link_int_a (&b), 1);
    CHECK_EQ ("INBUF holds the value", link_read_inbuf (&b), 054321);
    CHECK_EQ ("reading INBUF clears REQ A", link_read_csr (&b) & LINK_REQA, 0);
    CHECK_EQ ("and withdraws the request", link_int_a (&b), 0);
    link_deliver (&a, link_take_wire (&b));
    CHECK_EQ ("the read sets the writer's REQ B at the boundary", link_read_csr (&a) & LINK_REQB, LINK_REQB);
    link_write_csr (&a, LINK_IEB);
    CHECK_EQ ("INT ENB B with REQ B requests", link_int_b (&a), 1);
    link_write_outbuf (&a, 1);
    CHECK_EQ ("writing OUTBUF clears the writer's REQ B", link_read_csr (&a) & LINK_REQB, 0);
    link_set_lost (&a);
    link_init (&a);
    CHECK_EQ ("PEER LOST reads as bit 8 and survives INIT", link_read_csr (&a), LINK_LOST);
}

static ls_up up_for (uint64_t k)
{
    ls_up u;
    memset (&u, 0, sizeof u);
    u.quantum = k;
    return u;
}

static void world_boundary (void)
{
    ls_world w;
    static ls_down downs[LS_MEMBERS];
    ls_up ups[LS_MEMBERS];
    ls_event ev_x[2] = { { 0.0004, LS_EV_RUN, 0, 1, 0 }, { 0.0005, LS_EV_DAC, 0, 3000, 0 } };
    ls_event ev_y[1] = { { 0.0002, LS_EV_DAC, 0, 4000, 0 } };   /* y's machine names x: ignored */
    const ls_up *up_ptrs[LS_MEMBERS];
    const ls_event *ev_ptrs[LS_MEMBERS] = { ev_x, ev_y, NULL, NULL, NULL };
    const plant_command *no_commands[LS_MEMBERS] = { NULL, NULL, NULL, NULL, NULL };
    char *text = NULL;
    size_t size = 0;
    FILE *trace = open_memstream (&text, &size);
    ls_world_init (&w, 1983, 1000, trace);
    for (int m = 0; m < LS_MEMBERS; m++) { ups[m] = up_for (1); up_ptrs[m] = &ups[m]; }
    ups[0].n_events = 2;
    ups[1].n_events = 1;
    ups[LS_MAIN].links[2].sent = 1;
    ups[LS_MAIN].links[2].value = 0777;
    ups[2].links[0].taken = 1;
    ls_world_step (&w, 1, up_ptrs, ev_ptrs, no_commands, downs);
    CHECK_EQ ("the plant reaches the boundary (us)", (long) (downs[0].pl.now * 1e6 + 0.5), 1000);
    CHECK_EQ ("x's DAC write applied", downs[3].pl.ax[0].code, 3000);
    CHECK_EQ ("x's run line applied", downs[3].pl.ax[0].run, 1);
    CHECK_EQ ("a write naming another axis is ignored", downs[0].pl.ax[0].code == 3000 && downs[0].pl.ax[1].code == 2048, 1);
    CHECK_EQ ("the 11/23's link z reaches z", downs[2].links[0].value, 0777);
    CHECK_EQ ("z's read reaches the 11/23's link z", downs[LS_MAIN].links[2].taken, 1);
    CHECK_EQ ("nobody is lost", downs[LS_MAIN].lost, 0);
    fflush (trace);
    /* rows: header, samples at 0 and 1 ms (4 each), one DAC row */
    int rows = 0;
    for (char *p = text; *p; p++) rows += *p == '\n';
    CHECK_EQ ("trace rows: header + 2 samples x 4 axes + 1 DAC row", rows, 10);
    CHECK_EQ ("the trace starts with the usual columns", strncmp (text, plant_row_columns, strlen (plant_row_columns)), 0);
    char *status = world_status (&w, 1);
    CHECK_EQ ("the status names the word the 11/23 sent to z", strstr (status, "\"to_11_03\":[[1,511]]") != NULL, 1);
    CHECK_EQ ("the status: every member running", strstr (status, "\"y\":\"running\"") != NULL, 1);
    free (status);
    w.live &= ~(1u << 1);                       /* y's machine is gone */
    up_ptrs[1] = NULL;
    for (int m = 0; m < LS_MEMBERS; m++) { ups[m] = up_for (2); ups[m].n_events = 0; }
    ls_world_step (&w, 2, up_ptrs, ev_ptrs, no_commands, downs);
    CHECK_EQ ("a lost 11/03 is the 11/23's lost bit", downs[LS_MAIN].lost, 2);
    CHECK_EQ ("no END while the 11/23 lives", downs[0].flags & LS_END, 0);
    w.live &= ~(1u << LS_MAIN);
    up_ptrs[LS_MAIN] = NULL;
    ls_world_step (&w, 3, up_ptrs, ev_ptrs, no_commands, downs);
    CHECK_EQ ("the 11/23 gone: END for the 11/03s", downs[0].flags & LS_END, LS_END);
    fclose (trace);
    free (text);
}

/* The 11/23 sends x a move (command 1, value 2000), then polls its status ten
   times: the move's words leave the eight-word history, its value stays in "sent". */
static void sent_values_outlive_the_history (void)
{
    ls_world w;
    static ls_down downs[LS_MEMBERS];
    ls_up ups[LS_MEMBERS];
    const ls_up *up_ptrs[LS_MEMBERS];
    const ls_event *no_events[LS_MEMBERS] = { NULL, NULL, NULL, NULL, NULL };
    const plant_command *no_commands[LS_MEMBERS] = { NULL, NULL, NULL, NULL, NULL };
    uint16_t words[22] = { LS_COMMAND_BASE + 1, 2000 };
    for (int i = 2; i < 22; i += 2) { words[i] = LS_COMMAND_BASE + 4; words[i + 1] = 0; }
    ls_world_init (&w, 1983, 0, NULL);
    for (uint64_t k = 1; k <= 22; k++) {
        for (int m = 0; m < LS_MEMBERS; m++) { ups[m] = up_for (k); up_ptrs[m] = &ups[m]; }
        ups[LS_MAIN].links[0].sent = 1;
        ups[LS_MAIN].links[0].value = words[k - 1];
        ls_world_step (&w, k, up_ptrs, no_events, no_commands, downs);
    }
    char *status = world_status (&w, 22);
    CHECK_EQ ("the move's words have left the history", strstr (status, "[1,42241]") == NULL, 1);
    CHECK_EQ ("x's sent values: the move's 2000 and the last status poll's 0",
              strstr (status, "\"sent\":{\"1\":2000,\"4\":0}") != NULL, 1);
    CHECK_EQ ("y was sent nothing", strstr (status, "\"sent\":{}") != NULL, 1);
    free (status);
}

int main (void)
{
    link_handshake ();
    world_boundary ();
    sent_values_outlive_the_history ();
    printf ("%d checks, %d failed\n", checks, failures);
    return failures != 0;
}
