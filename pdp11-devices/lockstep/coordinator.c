/* coordinator.c: build/lockstep-coordinator, the one place the plant lives
   when the 11/23 and four LSI-11/03s run in lock-step (docs/controllers.md).

   lockstep-coordinator SOCKET [--trace FILE] [--sample N] [--seed N]
                        [--members LIST] [--join-timeout S] [--quanta N]
                        [--status FILE]
   listens on the Unix socket SOCKET (made here, removed at exit; put it in a
   private directory: the launcher's is mode 0700), waits for the members
   (LIST, default x,y,z,t,main: a subset for tests) to ATTACH LOCKSTEP, then
   runs the barrier (N quanta per simulated second, default 1000: a quantum
   is never longer than the plant's 1 ms grid step; more, shorter ones are
   allowed, for measuring their cost): quantum k ends when every live member has sent its ls_up
   for k; the plant and the links are stepped (lockstep/quantum.c) and each
   member gets its ls_down. SET PLANT typed at any member's sim> reaches
   this plant with that member's ls_up and is applied at the boundary
   (quantum.h). Only the wire is here: sockets, joining, losing.
   --status FILE: every 100 quanta (and when a member is lost or a SET PLANT
   was applied) FILE is
   replaced (written beside it, renamed) by the status (quantum.h), which the
   lab page shows; it changes nothing in the run.

   A member whose connection closes (killed, QUIT) is lost at once: the
   others go on without it (its axis keeps its last DAC code, as a dead
   controller's D/A would), the 11/23 sees PEER LOST on its link. When the
   11/23 goes, the others get LS_END and the coordinator exits 0. Nothing
   here reads the host's clock except the join timeout (a guard: members
   that never come). Exit 2: bad arguments or socket; 1: a member broke the
   protocol or never joined. */
#define _DEFAULT_SOURCE           /* sockets under -std=c99 */
#include <errno.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include "quantum.h"

static const char *const member_names[LS_MEMBERS] = { "x", "y", "z", "t", "main" };

typedef struct {
    int fd;                     /* -1: not joined or gone */
    int expected, joined, ready;
    ls_up up;
    ls_event events[LS_MAX_EVENTS];
    plant_command commands[LS_MAX_COMMANDS];
} member;

static member members[LS_MEMBERS];
static volatile sig_atomic_t stopping;
static const char *socket_path;
static const char *status_path;
#define STATUS_EVERY 100                /* quanta between status files */

static void write_status (const ls_world *w, uint64_t k)
{
    char tmp[4200];
    FILE *f;
    if (!status_path) return;
    snprintf (tmp, sizeof tmp, "%s.tmp", status_path);
    if (!(f = fopen (tmp, "w"))) return;
    ls_world_status (f, w, k);
    fclose (f);
    rename (tmp, status_path);
}

static void on_signal (int sig)
{
    (void) sig;
    stopping = 1;
}

static void die (int status, const char *what)
{
    fprintf (stderr, "lockstep-coordinator: %s\n", what);
    if (socket_path) unlink (socket_path);
    exit (status);
}

static void lose (ls_world *w, int m, const char *why)
{
    if (members[m].fd >= 0) close (members[m].fd);
    members[m].fd = -1;
    members[m].ready = 0;
    w->live &= ~(1u << m);
    fprintf (stderr, "lockstep-coordinator: %s %s\n", member_names[m], why);
}

static void join (ls_world *w, int listener)
{
    ls_hello h;
    ls_welcome wel;
    int fd = accept (listener, NULL, NULL);
    if (fd < 0) return;
    if (!ls_io_full (fd, &h, sizeof h, 0) || h.magic != LS_MAGIC || h.member >= LS_MEMBERS
        || !members[h.member].expected || members[h.member].joined) {
        fprintf (stderr, "lockstep-coordinator: refused a connection (not an expected member)\n");
        close (fd);
        return;
    }
    memset (&wel, 0, sizeof wel);
    wel.magic = LS_MAGIC;
    wel.quanta_per_s = w->quanta_per_s;
    wel.sample_hz = (uint32_t) w->sample_hz;
    wel.pl = w->pl;
    members[h.member].fd = fd;
    members[h.member].joined = 1;
    if (!ls_io_full (fd, &wel, sizeof wel, 1))
        lose (w, h.member, "left while joining");
}

static void receive (ls_world *w, int m, uint64_t k)
{
    member *mb = &members[m];
    if (!ls_io_full (mb->fd, &mb->up, sizeof mb->up, 0)) {
        lose (w, m, "lost (its connection closed)");
        return;
    }
    if (mb->up.quantum != k || mb->up.n_events > LS_MAX_EVENTS
        || mb->up.n_commands > LS_MAX_COMMANDS
        || !ls_io_full (mb->fd, mb->events, mb->up.n_events * sizeof (ls_event), 0)
        || !ls_io_full (mb->fd, mb->commands, mb->up.n_commands * sizeof (plant_command), 0)) {
        lose (w, m, "broke the protocol");
        return;
    }
    mb->ready = 1;
}

/* Every live member's ls_up for quantum k, joining late members meanwhile. */
static void gather (ls_world *w, int listener, uint64_t k, int join_timeout_ms)
{
    for (;;) {
        struct pollfd fds[LS_MEMBERS + 1];
        int who[LS_MEMBERS + 1], n = 0, waiting = 0;
        for (int m = 0; m < LS_MEMBERS; m++) {
            member *mb = &members[m];
            if (!mb->expected || !(w->live & (1u << m)) || mb->ready) continue;
            waiting = 1;
            if (mb->fd >= 0) {
                fds[n].fd = mb->fd; fds[n].events = POLLIN; who[n++] = m;
            }
        }
        if (!waiting) return;
        fds[n].fd = listener; fds[n].events = POLLIN; who[n++] = -1;
        int all_joined = 1;
        for (int m = 0; m < LS_MEMBERS; m++)
            if (members[m].expected && !members[m].joined) all_joined = 0;
        int r = poll (fds, n, all_joined ? -1 : join_timeout_ms);
        if (stopping) die (0, "stopped by a signal");
        if (r == 0) die (1, "a member did not join in time");
        if (r < 0) continue;
        for (int i = 0; i < n; i++) {
            if (!(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
            if (who[i] < 0) join (w, listener);
            else receive (w, who[i], k);
        }
    }
}

/* The socket appears under its name only once it listens (bound under a
   temporary name, then renamed): a member that finds the name can connect. */
static int listen_on (const char *path)
{
    struct sockaddr_un addr = { .sun_family = AF_UNIX };
    int fd = socket (AF_UNIX, SOCK_STREAM, 0);
    if (fd < 0 || strlen (path) + 4 >= sizeof addr.sun_path)
        die (2, "cannot make the socket (path too long?)");
    snprintf (addr.sun_path, sizeof addr.sun_path, "%s.new", path);
    unlink (addr.sun_path);
    unlink (path);
    if (bind (fd, (struct sockaddr *) &addr, sizeof addr) < 0 || listen (fd, LS_MEMBERS) < 0
        || rename (addr.sun_path, path) < 0)
        die (2, "cannot listen on the socket");
    socket_path = path;
    return fd;
}

static void expect_members (const char *list)
{
    char buf[64];
    snprintf (buf, sizeof buf, "%s", list);
    for (char *name = strtok (buf, ","); name; name = strtok (NULL, ",")) {
        int m;
        for (m = 0; m < LS_MEMBERS && strcmp (name, member_names[m]) != 0; m++)
            ;
        if (m == LS_MEMBERS) die (2, "--members takes x,y,z,t,main");
        members[m].expected = 1;
    }
}

int main (int argc, char **argv)
{
    const char *trace_path = NULL, *list = "x,y,z,t,main";
    int sample = 60, join_timeout_s = 60, quanta = LS_QUANTA_PER_S;
    unsigned long long seed = 1983;
    static ls_down downs[LS_MEMBERS];
    ls_world w;
    FILE *trace = NULL;
    if (argc < 2 || argv[1][0] == '-')
        die (2, "usage: lockstep-coordinator SOCKET [--trace FILE] [--sample N] [--seed N] "
             "[--members x,y,z,t,main] [--join-timeout S] [--quanta N] [--status FILE]");
    for (int i = 2; i + 1 < argc; i += 2) {
        if (!strcmp (argv[i], "--trace")) trace_path = argv[i + 1];
        else if (!strcmp (argv[i], "--sample")) sample = atoi (argv[i + 1]);
        else if (!strcmp (argv[i], "--seed")) seed = strtoull (argv[i + 1], NULL, 10);
        else if (!strcmp (argv[i], "--members")) list = argv[i + 1];
        else if (!strcmp (argv[i], "--join-timeout")) join_timeout_s = atoi (argv[i + 1]);
        else if (!strcmp (argv[i], "--quanta")) quanta = atoi (argv[i + 1]);
        else if (!strcmp (argv[i], "--status")) status_path = argv[i + 1];
        else die (2, "unknown option (see the file's header)");
    }
    if (argc % 2 != 0) die (2, "an option lacks its value");
    if (sample < 0 || sample > 1000) die (2, "--sample takes 0..1000");
    if (quanta < LS_QUANTA_PER_S || quanta > 100000)
        die (2, "--quanta takes 1000..100000 (a quantum no longer than the plant's 1 ms step)");
    signal (SIGPIPE, SIG_IGN);
    signal (SIGTERM, on_signal);
    signal (SIGINT, on_signal);
    expect_members (list);
    for (int m = 0; m < LS_MEMBERS; m++) members[m].fd = -1;
    int listener = listen_on (argv[1]);
    if (trace_path && !(trace = fopen (trace_path, "w")))
        die (2, "cannot write the trace");
    ls_world_init (&w, seed, sample, trace);
    w.quanta_per_s = quanta;
    for (int m = 0; m < LS_MEMBERS; m++)
        if (!members[m].expected) w.expected &= ~(1u << m);
    w.live = w.expected;
    uint32_t status_live = w.live;
    for (uint64_t k = 1;; k++) {
        const ls_up *ups[LS_MEMBERS];
        const ls_event *events[LS_MEMBERS];
        const plant_command *commands[LS_MEMBERS];
        gather (&w, listener, k, join_timeout_s * 1000);
        for (int m = 0; m < LS_MEMBERS; m++) {
            ups[m] = members[m].ready ? &members[m].up : NULL;
            events[m] = members[m].events;
            commands[m] = members[m].commands;
        }
        int set = ls_world_step (&w, k, ups, events, commands, downs);
        for (int m = 0; m < LS_MEMBERS; m++) {
            if (!members[m].ready) continue;
            members[m].ready = 0;
            if (!ls_io_full (members[m].fd, &downs[m], sizeof downs[m], 1))
                lose (&w, m, "lost (its connection closed)");
        }
        if (k % STATUS_EVERY == 0 || w.live != status_live || set) {
            write_status (&w, k);
            status_live = w.live;
        }
        if (members[LS_MAIN].expected && !(w.live & (1u << LS_MAIN)))
            break;                          /* the others were told: LS_END */
        if (w.live == 0) break;
    }
    if (trace) fclose (trace);
    unlink (argv[1]);
    return 0;
}
