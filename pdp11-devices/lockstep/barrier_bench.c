/* barrier_bench.c: build/barrier-bench, what one lock-step boundary costs on this
   host with nothing simulated, for the two designs issue 21 allowed (make
   bench-controllers prints it; docs/controllers.md says why the coordinator):
     star     the design built: five member processes each write a boundary
              message (sizeof ls_up) to a coordinator process over a Unix
              socket and block reading its answer (sizeof ls_down), which it
              sends once it has all five
     futex    five processes on one shared-memory barrier (a counter and a
              generation word, FUTEX_WAIT / FUTEX_WAKE): the last to arrive
              would step the plant and wake the others; no coordinator
   barrier-bench ROUNDS: prints "star <us per round>" and "futex <us per round>". */
#define _GNU_SOURCE
#include <linux/futex.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/mman.h>
#include <sys/socket.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "lockstep_wire.h"

static double now (void)
{
    struct timespec t;
    clock_gettime (CLOCK_MONOTONIC, &t);
    return t.tv_sec + t.tv_nsec * 1e-9;
}

static double star (long rounds)
{
    int fds[LS_MEMBERS][2];
    static ls_up up;
    static ls_down down;
    double t0 = now ();
    for (int m = 0; m < LS_MEMBERS; m++) {
        socketpair (AF_UNIX, SOCK_STREAM, 0, fds[m]);
        if (fork () == 0) {
            for (long r = 0; r < rounds; r++)
                if (!ls_io_full (fds[m][1], &up, sizeof up, 1) || !ls_io_full (fds[m][1], &down, sizeof down, 0))
                    _exit (1);
            _exit (0);
        }
    }
    for (long r = 0; r < rounds; r++) {
        for (int m = 0; m < LS_MEMBERS; m++) ls_io_full (fds[m][0], &up, sizeof up, 0);
        for (int m = 0; m < LS_MEMBERS; m++) ls_io_full (fds[m][0], &down, sizeof down, 1);
    }
    while (wait (NULL) > 0)
        ;
    return (now () - t0) / rounds * 1e6;
}

typedef struct { atomic_int arrived; atomic_int generation; } shared_barrier;

static void futex (atomic_int *addr, int op, int val)
{
    syscall (SYS_futex, addr, op, val, NULL, NULL, 0);
}

static void arrive (shared_barrier *b)
{
    int gen = atomic_load (&b->generation);
    if (atomic_fetch_add (&b->arrived, 1) == LS_MEMBERS - 1) {
        atomic_store (&b->arrived, 0);           /* the last: would step the plant here */
        atomic_fetch_add (&b->generation, 1);
        futex (&b->generation, FUTEX_WAKE, LS_MEMBERS);
    } else
        while (atomic_load (&b->generation) == gen)
            futex (&b->generation, FUTEX_WAIT, gen);
}

static double futex_barrier (long rounds)
{
    shared_barrier *b = mmap (NULL, sizeof *b, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
    double t0 = now ();
    atomic_init (&b->arrived, 0);
    atomic_init (&b->generation, 0);
    for (int m = 0; m < LS_MEMBERS; m++)
        if (fork () == 0) {
            for (long r = 0; r < rounds; r++) arrive (b);
            _exit (0);
        }
    while (wait (NULL) > 0)
        ;
    return (now () - t0) / rounds * 1e6;
}

int main (int argc, char **argv)
{
    long rounds = argc > 1 ? atol (argv[1]) : 20000;
    if (rounds <= 0) {
        fprintf (stderr, "usage: barrier-bench ROUNDS\n");
        return 2;
    }
    printf ("star %.2f\n", star (rounds));
    printf ("futex %.2f\n", futex_barrier (rounds));
    return 0;
}
