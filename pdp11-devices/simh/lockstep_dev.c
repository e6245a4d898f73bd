/* lockstep_dev.c: this simulator as one member of the five machines run in
   lock-step on one plant (SIMH device LOCKSTEP; no bus registers; the
   project's continuation of the paper, docs/controllers.md).

   SET LOCKSTEP ROLE=X|Y|Z|T   an LSI-11/03 axis controller: the AAV11-A's
                               channel 0 drives that axis (channels 1-3 read
                               back, drive nothing); the DRV11 at 167770
                               reads that axis's counter whatever CSR bits
                               1:0 say, OUTBUF bit 0 is its run line; one
                               link DRV11 at 167760 (LINK, bus/link_dev.c)
   SET LOCKSTEP ROLE=MAIN      the 11/23: DRV11 and AAV11-A present but
                               driving nothing (counters read 0, no gripper);
                               four link DRV11s at 167760/750/740/730
   SET LOCKSTEP ROLE=NONE      the ordinary machine (power-up: this device
                               changes nothing until a role is set)
   ATTACH LOCKSTEP socket      joins the coordinator (build/lockstep-
                               coordinator) listening there, at simulated
                               time 0 only; DETACH leaves
   SHOW LOCKSTEP               role, quantum, boundaries passed, lost peers

   How (lockstep_wire.h): every 1/quanta_per_s simulated seconds (an exact
   series of instruction counts, clock_share) an event sends this member's
   DAC writes and run-line changes of the quantum, with their simulated times,
   and what its links did, then waits for the coordinator's answer: the plant
   at the boundary and what crossed the links. Counter reads within a quantum
   are answered from a local copy of that plant advanced to the read's time
   with this member's own writes applied, so they are exact (the same
   integration the coordinator then does); only the authoritative plant,
   the trace and the other axes live in the coordinator. The wait blocks the
   host thread: while another member is stopped (at its sim>), this one
   waits at its boundary and simulated time stands still for all.

   SET PLANT and SHOW PLANT on any member act on the coordinator's plant
   (plant_dev.c asks lockstep_plant_command and lockstep_plant_shown): a
   setting is checked at once against that plant as of the last boundary
   (with this member's earlier settings of the quantum), refused there with
   the plant's own message, or kept and sent with this quantum's events, to
   be applied by the coordinator at the boundary that ends the quantum: the
   same simulated moment for every member, however long this one stood at
   its sim>. SHOW PLANT shows that plant as of the last boundary (its state
   is the coordinator's, exactly), the settings still to come applied.

   The 11/23 prints one line at its console when an 11/03 is lost ("11/03
   axis y stopped: ...") and its link's CSR bit 8 sets; an 11/03 whose
   coordinator or 11/23 is gone stops at sim> with a message. */
#include "devices.h"
#include "lockstep_wire.h"

#include <errno.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

extern int32 sim_is_running;

int lockstep_role = LOCKSTEP_NONE;
static const char *const role_names[] = { "X", "Y", "Z", "T", "MAIN" };
static plant local;                      /* the plant as of the last boundary, then advanced */
static plant boundary;                   /* the coordinator's plant at the last boundary */
static uint32 boundary_sample_hz;        /* its trace's samples per second */
static plant_command pending[LS_MAX_COMMANDS];   /* SET PLANT of this quantum */
static int n_pending;
static int sock = -1;
static ls_up up;
static ls_event events[LS_MAX_EVENTS];
static uint32 dropped;                   /* events past LS_MAX_EVENTS in one quantum */
static int32 quanta_per_s = LS_QUANTA_PER_S, quantum_acc;
static uint32 lost_told;

static t_stat ls_svc (UNIT *uptr);
static t_stat ls_attach (UNIT *uptr, char *cptr);
static t_stat ls_detach (UNIT *uptr);
static t_stat ls_set_role (UNIT *uptr, int32 val, char *cptr, void *desc);
static t_stat ls_show (FILE *st, UNIT *uptr, int32 val, void *desc);

static UNIT ls_unit = { UDATA (&ls_svc, UNIT_ATTABLE, 0) };

static MTAB ls_mod[] = {
    { MTAB_XTD|MTAB_VDV, 0, NULL, "ROLE", &ls_set_role, NULL, NULL },
    { MTAB_XTD|MTAB_VDV, 0, "STATE", NULL, NULL, &ls_show, NULL },
    { 0 }
};

DEVICE lockstep_dev = {
    "LOCKSTEP", &ls_unit, NULL, ls_mod,
    1, 10, 31, 1, 8, 16,
    NULL, NULL, NULL,
    NULL, &ls_attach, &ls_detach,
    NULL, 0
};

static void reset_local (void)
{
    plant_init (&local, 1983);            /* replaced by the coordinator's at ATTACH */
    boundary = local;
    n_pending = 0;
}

static t_stat ls_set_role (UNIT *uptr, int32 val, char *cptr, void *desc)
{
    int role;
    if (ls_unit.flags & UNIT_ATT) {
        printf ("LOCKSTEP: DETACH LOCKSTEP before changing the role\n");
        return SCPE_ARG;
    }
    if (cptr != NULL && strcmp (cptr, "NONE") == 0)
        role = LOCKSTEP_NONE;
    else {
        for (role = 0; role < LS_MEMBERS && (cptr == NULL || strcmp (cptr, role_names[role])); role++)
            ;
        if (role == LS_MEMBERS) {
            printf ("LOCKSTEP: ROLE is X, Y, Z, T (an 11/03 axis controller), MAIN (the 11/23) or NONE\n");
            return SCPE_ARG;
        }
    }
    lockstep_role = role;
    reset_local ();
    link_dev_configure (role == LOCKSTEP_NONE ? 0 : role == LS_MAIN ? LS_LINKS : 1);
    return SCPE_OK;
}

static t_stat ls_attach (UNIT *uptr, char *cptr)
{
    struct sockaddr_un addr = { .sun_family = AF_UNIX };
    ls_hello hello = { LS_MAGIC, 0, (int32_t) getpid (), 0 };
    ls_welcome wel;
    if (lockstep_role == LOCKSTEP_NONE) {
        printf ("LOCKSTEP: SET LOCKSTEP ROLE=... first\n");
        return SCPE_ARG;
    }
    if (sim_gtime () != 0) {
        printf ("LOCKSTEP: ATTACH before the machine runs (at simulated time 0)\n");
        return SCPE_ARG;
    }
    if (uptr->flags & UNIT_ATT)
        ls_detach (uptr);
    if (strlen (cptr) >= sizeof addr.sun_path) {
        printf ("LOCKSTEP: socket path too long\n");
        return SCPE_ARG;
    }
    strcpy (addr.sun_path, cptr);
    hello.member = (uint32_t) lockstep_role;
    sock = socket (AF_UNIX, SOCK_STREAM, 0);
    if (sock < 0 || connect (sock, (struct sockaddr *) &addr, sizeof addr) < 0
        || !ls_io_full (sock, &hello, sizeof hello, 1) || !ls_io_full (sock, &wel, sizeof wel, 0)
        || wel.magic != LS_MAGIC) {
        printf ("LOCKSTEP: cannot join the coordinator at %s: %s\n", cptr,
                errno ? strerror (errno) : "refused");
        if (sock >= 0) close (sock);
        sock = -1;
        return SCPE_OPENERR;
    }
    local = boundary = wel.pl;
    boundary_sample_hz = wel.sample_hz;
    n_pending = 0;
    quanta_per_s = (int32) wel.quanta_per_s;
    quantum_acc = 0;
    memset (&up, 0, sizeof up);
    lost_told = 0;
    /* SHOW says "attached to" this: the socket's name, not its (temporary) directory,
       so that a scripted run's transcript is the same every run */
    const char *name = strrchr (cptr, '/') ? strrchr (cptr, '/') + 1 : cptr;
    uptr->filename = (char *) calloc (strlen (name) + 1, 1);
    strcpy (uptr->filename, name);
    uptr->flags |= UNIT_ATT;
    sim_activate (uptr, clock_share (quanta_per_s, &quantum_acc));
    return SCPE_OK;
}

static t_stat ls_detach (UNIT *uptr)
{
    if (!(uptr->flags & UNIT_ATT))
        return SCPE_OK;
    sim_cancel (uptr);
    if (sock >= 0) close (sock);
    sock = -1;
    free (uptr->filename);
    uptr->filename = NULL;
    uptr->flags &= ~UNIT_ATT;
    return SCPE_OK;
}

/* An 11/03 was lost: its link says so, and the 11/23's console once. */
static void tell_lost (uint32 lost)
{
    for (int a = 0; a < LS_LINKS; a++) {
        if (!(lost & ~lost_told & (1u << a))) continue;
        link_dev_peer_lost (a);
        printf ("\r\n11/03 axis %c stopped: its simulator is gone (link %c CSR bit 8 set)\r\n",
                plant_axis_names[a] + ('a' - 'A'), plant_axis_names[a] + ('a' - 'A'));
        fflush (stdout);
    }
    lost_told |= lost;
}

static t_stat ls_svc (UNIT *uptr)
{
    ls_down down;
    int n = up.n_events;
    up.quantum++;
    for (int i = 0; i < LS_LINKS; i++)
        up.links[i] = link_dev_take_wire (i);
    up.n_commands = (uint32_t) n_pending;
    if (!ls_io_full (sock, &up, sizeof up, 1) || !ls_io_full (sock, events, n * sizeof (ls_event), 1)
        || !ls_io_full (sock, pending, n_pending * sizeof (plant_command), 1)
        || !ls_io_full (sock, &down, sizeof down, 0) || down.quantum != up.quantum) {
        ls_detach (uptr);
        printf ("\r\nLOCKSTEP: the coordinator is gone; this machine stops\r\n");
        return SCPE_STOP;
    }
    up.n_events = 0;
    n_pending = 0;
    local = boundary = down.pl;
    boundary_sample_hz = down.sample_hz;
    if (down.refused) {
        printf ("\r\nPLANT: %u SET PLANT setting(s) from this sim> refused at the boundary: "
                "another machine's SET of the same quantum came first (SHOW PLANT)\r\n", down.refused);
        fflush (stdout);
    }
    for (int i = 0; i < LS_LINKS; i++)
        link_dev_deliver (i, down.links[i]);
    if (lockstep_role == LS_MAIN)
        tell_lost (down.lost);
    if (down.flags & LS_END) {
        ls_detach (uptr);
        printf ("\r\nLOCKSTEP: the 11/23 has left; the session is over\r\n");
        return SCPE_STOP;
    }
    sim_activate (uptr, clock_share (quanta_per_s, &quantum_acc));
    return SCPE_OK;
}

static void record (int kind, int value)
{
    double t = clock_time ();
    if (!(ls_unit.flags & UNIT_ATT))
        return;
    if (up.n_events == LS_MAX_EVENTS) {
        dropped++;
        return;
    }
    ls_event *e = &events[up.n_events++];
    e->t = t;
    e->kind = (uint16) kind;
    e->axis = (uint16) lockstep_role;
    e->value = (uint16) value;
    e->pad = 0;
}

void lockstep_dac (int channel, int code)
{
    if (lockstep_role == LS_MAIN || channel != 0)
        return;
    plant_advance (&local, clock_time ());
    plant_set_code (&local, lockstep_role, code);
    record (LS_EV_DAC, code);
}

void lockstep_run_lines (int lines)
{
    if (lockstep_role == LS_MAIN || local.ax[lockstep_role].run == (lines & 1))
        return;
    plant_advance (&local, clock_time ());
    plant_set_run (&local, lockstep_role, lines & 1);
    record (LS_EV_RUN, lines & 1);
}

uint16 lockstep_counter (void)
{
    if (lockstep_role == LS_MAIN)
        return 0;
    plant_advance (&local, clock_time ());
    return plant_counter (&local, lockstep_role);
}

const char *lockstep_plant_command (const plant_command *c)
{
    plant after;
    int hz;
    const char *why;
    if (!(ls_unit.flags & UNIT_ATT))
        return "this machine has no lock-step coordinator now (ATTACH LOCKSTEP joins one)";
    if (n_pending == LS_MAX_COMMANDS)
        return "too many settings before the next boundary: CONT a moment, then SET again";
    lockstep_plant_shown (&after, &hz);
    if ((why = plant_command_apply (&after, c)) != NULL)
        return why;
    pending[n_pending++] = *c;
    return NULL;
}

int lockstep_plant_shown (plant *pl, int *sample_hz)
{
    *pl = boundary;
    *sample_hz = (int) boundary_sample_hz;
    for (int i = 0; i < n_pending; i++) {
        plant_command_apply (pl, &pending[i]);
        if (pending[i].kind == PC_SAMPLE)
            *sample_hz = (int) pending[i].value;
    }
    return n_pending;
}

void lockstep_rate_changed (int32 old_rate)
{
    clock_rescale (&ls_unit, old_rate);
    quantum_acc = 0;
}

static t_stat ls_show (FILE *st, UNIT *uptr, int32 val, void *desc)
{
    if (lockstep_role == LOCKSTEP_NONE) {
        fprintf (st, "role=none (the ordinary machine)");
        return SCPE_OK;
    }
    fprintf (st, "role=%s, quantum=%.3f ms, boundaries=%llu, %s", role_names[lockstep_role],
             1000.0 / quanta_per_s, (unsigned long long) up.quantum,
             (uptr->flags & UNIT_ATT) ? "joined" : "not joined");
    if (lockstep_role == LS_MAIN && lost_told) {
        fprintf (st, ", lost:");
        for (int a = 0; a < LS_LINKS; a++)
            if (lost_told & (1u << a)) fprintf (st, " %c", plant_axis_names[a]);
    }
    if (lockstep_role != LS_MAIN)
        fprintf (st, ", axis pos=%.3f counter=%d dac=%04d", local.ax[lockstep_role].p,
                 (int) (int16) plant_counter (&local, lockstep_role), local.ax[lockstep_role].code);
    if (dropped)
        fprintf (st, ", %u events dropped (over %d in a quantum)", dropped, LS_MAX_EVENTS);
    return SCPE_OK;
}
