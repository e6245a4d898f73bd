/* lab.c: the lab bench's window onto the running machine (SIMH device LAB).
   No bus registers: the program cannot see it. It reads memory words, paces
   the run to the wall clock, and pauses it, all at the 60 Hz tick boundaries.

   ATTACH LAB path: rows go to `path` (a FIFO the lab server reads, or a
   file); commands are read, when it exists, from the FIFO `path.ctl`.
   Attach before the machine starts (the lab's boot script does): its ticks
   then fall on the KW11-L's, once every RATE/60 instructions (exactly, when
   RATE is a multiple of 240, as the default 300000 is).
   DETACH LAB closes both and ends any pause.

   Rows, one per line, numbers in decimal:
     W,time_s,tick,w0,w1,...   at every tick: simulated seconds, the tick's
                               number since the attach, the watched words (0..65535)
     P,time_s,axis,dac,vcmd,vel,pos,counter,grip,contact,missed
                               the plant, per axis, four times a tick: the
                               plant trace's row (plant_dev_write_row; SHOW
                               PLANT LAYOUT names its columns)
     A,a0,a1,...               the watched addresses (octal), when they change
     S,time_s,state,speed,power,clock,timable
                               state run|pause, the amplifier rack on|off
                               (PLANT POWER), the time base count|timed (SET
                               CLK TIMED: the KDF11-A's instruction times),
                               timable 1 when this simulator's CPU prices
                               instructions (build/pdp11-timed), else 0;
                               after every command and time base change
     M,addr,w0,...             memory (addr octal, up to 64 words a row): a dump
     R,time_s,r0,...,r7,psw,(r4),lks,csr,outbuf,dac0,...,dac3,m0,...
                               the front panel, at every reported tick once
                               `panel` asked for it, all octal: the registers
                               (the current set, r7 = PC), the PSW, the word
                               R4 (the FORTH's IP) points at, the KW11-L's LKS,
                               the DRV11's CSR and OUTBUF, the AAV11-A's four
                               DACs (read through their SIMH register tables),
                               then the words at the panel's addresses
     I,time_s,v=n,...          with each R row: for each vector the CPU has
                               taken an interrupt at (octal), how many times
                               since power-up (interrupt_count.c)
     E,what                    a command refused, and why
   Commands, one per line (harness/lab/protocol.py's DEVICE_COMMANDS is the
   server's copy of this list and of the rows above; tests/lab/test_lab_device.py
   holds the three together):
     speed X     pace at X times the 11/23's (RATE instructions per wall
                 second), 0 < X <= 1000; 0 = full speed (the power-up setting)
     pause       stop simulated time at the next tick (the plant stops with it)
     run         go on
     step        one tick more, then pause again
     watch a...  octal even addresses below 160000 (at most 64); none = clear
     dump a n    n words from octal address a (at most 28672)
     power on|off  the amplifier rack's switch (SET PLANT POWER), between
                 two ticks like every command
     panel [a...]  R rows from now on, with the words at octal addresses a...
                 (at most 8; the lab gives BLK and >IN); `panel off` stops them
     halt        stop the machine at sim> at the next tick (a paused run at
                 once): "Simulation stopped", as ^E, but at a tick, and
                 answered while paused, when ^E waits; CONT goes on (still
                 paused if it was). Instructions STEPped there pass the next
                 tick without pausing (the front panel's step never hangs)
     clock count|timed  the time base, as SET CLK NOTIMED|TIMED, between two
                 ticks: simulated time stays continuous, the pace (speed X)
                 is in the new base's seconds; timed is refused where the
                 CPU does not price instructions (build/pdp11)
   A bad command is answered by an E row and changes nothing.

   Reporting: up to ten times the 11/23's pace every tick is reported. Faster
   than that (full speed) a tick's W and P rows are written only when 1/60 s
   of wall time has passed since the last reported tick, so the simulator
   formats and writes about 60 ticks a wall second whatever its speed: the
   page sees snapshots, and the run loses little to its observer. Between two
   reported ticks the device looks (at commands, at the wall clock) at about
   two ticks, at most 60 ticks (1 simulated second) apart: a pause then
   stops time at the tick it looks at next.

   Determinism: the wall clock only decides when the host sleeps; what the
   machine does at each instruction count is the same at any speed and with
   any pauses. While paused the simulator waits for commands, so typed keys
   (^E too) wait in the terminal until the run goes on. When the command FIFO
   loses its writer (the lab server exited) a pause ends by itself.

   SET LAB SPEED=X as the command; SHOW LAB: state, speed, watched words.
   SHOW LAB PANEL: the registers and the PSW at the console, and an R and an
   I row to the lab (the front panel after a STEP at sim>). SHOW LAB
   INTERRUPTS: the interrupts taken per vector. SET LAB IOBREAK=addr, SET LAB
   NOIOBREAK, SHOW LAB IOBREAK: a breakpoint on an I/O register (io_break.c). */
#include "devices.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <unistd.h>

#define TICKS_PER_S  60
#define SUBSAMPLES   4                  /* plant samples per tick */
#define REPORT_S     (1.0 / 60)         /* wall seconds between ticks reported, when fast */
#define REPORT_ALL   10.0               /* up to this speed every tick is reported */
#define SKIP_MAX     60                 /* ticks passed over at most, when fast */
#define WATCH_MAX    64
#define DUMP_ROW     64
#define MEM_TOP      0160000            /* the I/O page starts here */
#define SPEED_MAX    1000.0
#define LATE_S       0.25               /* further behind the wall than this: a new reference */
#define CMD_MAX      1024

extern uint16 *M;
extern int32 R[8];                      /* pdp11_cpu.c: the current register set */
int32 get_PSW (void);
t_value get_rval (REG *rptr, uint32 idx);    /* scp.c, not in scp.h */
#define PANEL_MAX    8

static double speed;                    /* 0 = full speed */
static int paused, steps, halting;
static int halted;                      /* at sim> by `halt`: STEP there passes the next tick */
extern int32 sim_step;                  /* scp.c: instructions a STEP has left, 0 otherwise */
static clock_series samples_due;         /* the sample series (time_base.c) */
static int sub;                         /* sample within the tick, 0 at the tick */
static int reporting;                   /* this tick's rows are written */
static double reported_wall;            /* when the last reported tick was */
static uint32 reported_tick;
static int32 skip = 1;                  /* ticks from one look to the next, when fast */
static uint32 tick_no;
static int ctl_fd = -1;
static char cmd_buf[CMD_MAX];
static int cmd_len;
static int32 watch[WATCH_MAX];
static int watch_n;
static int panel = 0;                   /* R rows wanted */
static int32 panel_at[PANEL_MAX];
static int panel_n;
static wall_pacer pacer;                 /* wall_pacer.c */

static t_stat lab_svc (UNIT *uptr);
static t_stat lab_attach (UNIT *uptr, char *cptr);
static t_stat lab_detach (UNIT *uptr);
static t_stat lab_set_speed (UNIT *uptr, int32 val, char *cptr, void *desc);
static t_stat lab_show (FILE *st, UNIT *uptr, int32 val, void *desc);
static t_stat lab_show_panel (FILE *st, UNIT *uptr, int32 val, void *desc);
static t_stat lab_show_interrupts (FILE *st, UNIT *uptr, int32 val, void *desc);
static t_stat lab_set_iobreak (UNIT *uptr, int32 val, char *cptr, void *desc);
static t_stat lab_show_iobreak (FILE *st, UNIT *uptr, int32 val, void *desc);

static UNIT lab_unit = { UDATA (&lab_svc, UNIT_ATTABLE, 0) };

static MTAB lab_mod[] = {
    { MTAB_XTD|MTAB_VDV, 0, "STATE", "SPEED", &lab_set_speed, &lab_show, NULL },
    { MTAB_XTD|MTAB_VDV|MTAB_NMO, 0, "PANEL", NULL, NULL, &lab_show_panel, NULL },
    { MTAB_XTD|MTAB_VDV|MTAB_NMO, 0, "INTERRUPTS", NULL, NULL, &lab_show_interrupts, NULL },
    { MTAB_XTD|MTAB_VDV|MTAB_NMO, 1, "IOBREAK", "IOBREAK", &lab_set_iobreak, &lab_show_iobreak, NULL },
    { MTAB_XTD|MTAB_VDV, 0, NULL, "NOIOBREAK", &lab_set_iobreak, NULL, NULL },
    { 0 }
};

DEVICE lab_dev = {
    "LAB", &lab_unit, NULL, lab_mod,
    1, 10, 31, 1, 8, 16,
    NULL, NULL, NULL,
    NULL, &lab_attach, &lab_detach,
    NULL, 0
};

static void rebase (void)                /* pace from here on */
{
    wall_pacer_drop (&pacer);
}

static FILE *out (void)
{
    return (lab_unit.flags & UNIT_ATT) ? lab_unit.fileref : NULL;
}

static void say_state (void)
{
    if (out ())
        fprintf (out (), "S,%.6f,%s,%g,%s,%s,%d\n", clock_time (), paused ? "pause" : "run", speed,
                 plant_dev_powered () ? "on" : "off", kdf11_timed ? "timed" : "count",
                 kdf11_time_possible ());
}

static void say_watch (void)
{
    if (!out ()) return;
    fputc ('A', out ());
    for (int i = 0; i < watch_n; i++)
        fprintf (out (), ",%o", watch[i]);
    fputc ('\n', out ());
}

static const char *parse_speed (const char *text, double *x)
{
    char *end;
    double v = strtod (text, &end);
    while (*end == ' ') end++;
    if (end == text || *end != 0 || !(v >= 0 && v <= SPEED_MAX))
        return "speed takes a number from 0 (full speed) to 1000 (times the 11/23's pace)";
    *x = v;
    return NULL;
}

static int parse_address (const char *word, int32 *a)
{
    char *end;
    long v = strtol (word, &end, 8);
    if (end == word || *end != 0 || v < 0 || v >= MEM_TOP || (v & 1)) return 0;
    *a = (int32) v;
    return 1;
}

/* A list of addresses into list[max]; 0 if one is bad or there are too many. */
static int parse_addresses (char *args, int32 *list, int max, int *n)
{
    *n = 0;
    for (char *w = strtok (args, " "); w; w = strtok (NULL, " "))
        if (*n == max || !parse_address (w, &list[(*n)++]))
            return 0;
    return 1;
}

static const char *set_watch (char *args)
{
    int32 list[WATCH_MAX];
    int n;
    if (!parse_addresses (args, list, WATCH_MAX, &n))
        return "watch takes at most 64 even octal addresses below 160000";
    memcpy (watch, list, sizeof list);
    watch_n = n;
    say_watch ();
    return NULL;
}

static const char *set_panel (char *args)
{
    int32 list[PANEL_MAX];
    int n;
    if (strcmp (args, "off") == 0) {
        panel = 0;
        return NULL;
    }
    if (!parse_addresses (args, list, PANEL_MAX, &n))
        return "panel takes at most 8 even octal addresses below 160000, or off";
    memcpy (panel_at, list, sizeof list);
    panel_n = n;
    panel = 1;
    return NULL;
}

static t_value device_reg (DEVICE *dptr, char *name, uint32 idx)
{
    REG *r = find_reg (name, NULL, dptr);
    return r ? get_rval (r, idx) : 0;
}

static void write_panel (void)
{
    int32 ip = R[4] & 0177776;
    fprintf (out (), "R,%.6f", clock_time ());
    for (int i = 0; i < 8; i++)
        fprintf (out (), ",%o", (int) (R[i] & 0177777));
    fprintf (out (), ",%o,%o", (int) (get_PSW () & 0177777), ip < MEM_TOP ? M[ip >> 1] : 0);
    fprintf (out (), ",%o,%o,%o", (int) device_reg (&kwl_dev, "LKS", 0),
             (int) device_reg (&drv_dev, "CSR", 0), (int) device_reg (&drv_dev, "OUTBUF", 0));
    for (int i = 0; i < PLANT_AXES; i++)
        fprintf (out (), ",%o", (int) device_reg (&aav_dev, "DAC", i));
    for (int i = 0; i < panel_n; i++)
        fprintf (out (), ",%o", M[panel_at[i] >> 1]);
    fprintf (out (), "\nI,%.6f", clock_time ());
    interrupt_count_write (out (), ",");
    fputc ('\n', out ());
}

static const char *dump (char *args)
{
    char *a_text = strtok (args, " "), *n_text = strtok (NULL, " "), *end;
    int32 a;
    long n = n_text ? strtol (n_text, &end, 10) : -1;
    if (!a_text || !parse_address (a_text, &a) || n < 1 || *end != 0
        || a + 2 * n > MEM_TOP || strtok (NULL, " "))
        return "dump takes an even octal address and a count of words inside memory";
    for (long i = 0; i < n; i++) {
        if (i % DUMP_ROW == 0)
            fprintf (out (), "%sM,%o", i ? "\n" : "", (int) (a + 2 * i));
        fprintf (out (), ",%d", M[(a >> 1) + i]);
    }
    fputc ('\n', out ());
    return NULL;
}

static const char *set_clock (const char *args)
{
    int timed = strcmp (args, "timed") == 0;
    if (!timed && strcmp (args, "count") != 0)
        return "clock takes count or timed";
    if (timed && !kdf11_time_possible ())
        return "clock timed needs the CPU that prices instructions: build/pdp11-timed "
               "(python -m harness lab --timed)";
    kdf11_time_set (timed);             /* the rate hooks: this device's rebase() too */
    return NULL;
}

static void command (char *line)
{
    const char *why = NULL;
    char *args = strchr (line, ' ');
    if (args) *args++ = 0; else args = line + strlen (line);
    if (strcmp (line, "speed") == 0) {
        if ((why = parse_speed (args, &speed)) == NULL) rebase ();
    } else if (strcmp (line, "pause") == 0)
        paused = 1;
    else if (strcmp (line, "run") == 0)
        paused = 0, steps = 0;
    else if (strcmp (line, "step") == 0)
        steps++;
    else if (strcmp (line, "watch") == 0)
        why = set_watch (args);
    else if (strcmp (line, "dump") == 0)
        why = dump (args);
    else if (strcmp (line, "power") == 0 && (strcmp (args, "on") == 0 || strcmp (args, "off") == 0))
        plant_dev_power (strcmp (args, "on") == 0);
    else if (strcmp (line, "power") == 0)
        why = "power takes on or off";
    else if (strcmp (line, "panel") == 0)
        why = set_panel (args);
    else if (strcmp (line, "halt") == 0)
        halting = 1;
    else if (strcmp (line, "clock") == 0)
        why = set_clock (args);
    else if (*line)
        why = "commands: speed X, pause, run, step, watch ADDR..., dump ADDR N, power on|off, "
              "panel [ADDR...|off], halt, clock count|timed";
    if (why && out ())
        fprintf (out (), "E,%s\n", why);
    say_state ();
}

/* Read what the server wrote; 0 when it has closed its end. */
static int read_commands (void)
{
    ssize_t got;
    if (ctl_fd < 0) return 0;
    while ((got = read (ctl_fd, cmd_buf + cmd_len, CMD_MAX - 1 - cmd_len)) > 0) {
        char *nl;
        cmd_len += (int) got;
        cmd_buf[cmd_len] = 0;
        while ((nl = strchr (cmd_buf, '\n')) != NULL) {
            *nl = 0;
            command (cmd_buf);
            cmd_len -= (int) (nl + 1 - cmd_buf);
            memmove (cmd_buf, nl + 1, cmd_len + 1);
        }
        if (cmd_len == CMD_MAX - 1) cmd_len = 0;      /* an overlong line: dropped */
    }
    return got != 0 || errno == EAGAIN;
}

static void write_sample (void)
{
    fprintf (out (), "W,%.6f,%u", clock_time (), tick_no);
    for (int i = 0; i < watch_n; i++)
        fprintf (out (), ",%d", M[watch[i] >> 1]);
    fputc ('\n', out ());
}

static void write_plant (void)
{
    plant_dev_catch_up ();
    for (int i = 0; i < PLANT_AXES; i++) {
        fputs ("P,", out ());
        plant_dev_write_row (out (), i);
    }
}

/* Fast runs: a tick is reported when 1/60 s of wall time has passed since the
   last one, and the device looks at about two ticks per reported one (at most
   SKIP_MAX apart), so it adds one event a simulated second, not 240, to a run
   that idles in WAIT, where SIMH's time leaps from event to event. */
static int report_this_tick (void)
{
    double now;
    if (speed > 0 && speed <= REPORT_ALL) {
        skip = 1;
        return 1;
    }
    now = wall_seconds ();
    if (now - reported_wall < REPORT_S)
        return 0;
    skip = (int32) (tick_no - reported_tick) / 2;
    skip = skip < 1 ? 1 : (skip > SKIP_MAX ? SKIP_MAX : skip);
    reported_wall = now;
    reported_tick = tick_no;
    return 1;
}

static void flush_all (void)
{
    fflush (out ());
}

static void pace (void)
{
    if (speed <= 0) return;
    wall_pacer_pace (&pacer, speed, LATE_S);
}

static void wait_while_paused (int stepping)
{
    struct pollfd p = { ctl_fd, POLLIN, 0 };
    if (!paused || steps > 0 || halting || stepping) return;
    say_state ();
    flush_all ();
    while (paused && steps == 0 && !halting) {
        if (poll (&p, 1, 200) > 0 && !read_commands ())
            paused = 0;                         /* the server is gone: run on */
        flush_all ();
    }
    rebase ();
}

/* The next event: the next sample, or, when this tick is not reported, the next
   tick the device looks at (the samples' intervals added up, so the series
   stays exact and every look falls on a tick). */
static void schedule (UNIT *uptr)
{
    int32 *acc = &samples_due.acc;
    int32 n = clock_share (TICKS_PER_S * SUBSAMPLES, acc);
    if (!reporting) {
        while (sub < SUBSAMPLES - 1) {              /* to the next tick */
            n += clock_share (TICKS_PER_S * SUBSAMPLES, acc);
            sub++;
        }
        for (int32 k = 1; k < skip; k++) {          /* and over skip - 1 more */
            for (int i = 0; i < SUBSAMPLES; i++)
                n += clock_share (TICKS_PER_S * SUBSAMPLES, acc);
            tick_no++;
        }
    }
    clock_series_activate (uptr, &samples_due, n);
}

static t_stat lab_svc (UNIT *uptr)
{
    if (!out ()) return SCPE_OK;
    sub = (sub + 1) % SUBSAMPLES;
    if (sub == 0) {                             /* a 60 Hz tick */
        tick_no++;
        read_commands ();
        if (steps > 0 && --steps == 0) paused = 1;
        reporting = report_this_tick () || paused || steps > 0;
        if (reporting)
            write_sample ();
        if (reporting && panel)
            write_panel ();
    }
    if (reporting)
        write_plant ();
    if (sub == 0) {
        int stepping = halted && sim_step;      /* instructions stepped at sim> after `halt` */
        halted = 0;
        wait_while_paused (stepping);
        if (reporting)
            flush_all ();
        pace ();
    }
    schedule (uptr);
    if (sub == 0 && halting) {                   /* `halt`: to sim>, between two ticks */
        halting = 0;
        halted = 1;
        flush_all ();
        return SCPE_STOP;
    }
    return SCPE_OK;
}

void lab_rate_changed (int32 old_rate)
{
    clock_series_rescale (&lab_unit, &samples_due, old_rate);   /* the next sample keeps its time */
    rebase ();
    say_state ();                               /* SET CLK TIMED at sim>: the page's clock too */
    if (out ())
        flush_all ();
}

static t_stat lab_attach (UNIT *uptr, char *cptr)
{
    t_stat r;
    char *ctl;
    if (uptr->flags & UNIT_ATT)
        lab_detach (uptr);
    signal (SIGPIPE, SIG_IGN);                  /* a vanished reader is no reason to stop */
    if ((ctl = (char *) malloc (strlen (cptr) + 5)) == NULL)
        return SCPE_MEM;
    if ((r = device_attach_text (uptr, cptr, "LAB: cannot write")) != SCPE_OK) {
        free (ctl);
        return r;
    }
    sprintf (ctl, "%s.ctl", cptr);
    ctl_fd = open (ctl, O_RDONLY | O_NONBLOCK);
    free (ctl);
    tick_no = reported_tick = 0;
    skip = 1;
    sub = 0;
    reporting = 1;
    cmd_len = 0;
    rebase ();
    say_watch ();
    say_state ();
    clock_series_start (&samples_due);
    clock_series_next (uptr, &samples_due, TICKS_PER_S * SUBSAMPLES);
    return SCPE_OK;
}

static t_stat lab_detach (UNIT *uptr)
{
    if (!(uptr->flags & UNIT_ATT))
        return SCPE_OK;
    sim_cancel (uptr);
    device_detach_text (uptr);
    if (ctl_fd >= 0) close (ctl_fd);
    ctl_fd = -1;
    paused = steps = panel = halting = 0;
    return SCPE_OK;
}

static t_stat lab_set_speed (UNIT *uptr, int32 val, char *cptr, void *desc)
{
    double x;
    const char *why = cptr ? parse_speed (cptr, &x) : "SPEED needs a value";
    if (why) {
        printf ("LAB: %s\n", why);
        return SCPE_ARG;
    }
    speed = x;
    rebase ();
    return SCPE_OK;
}

static t_stat lab_show (FILE *st, UNIT *uptr, int32 val, void *desc)
{
    fprintf (st, "%s, speed=%g%s, %d words watched", paused ? "paused" : "running", speed,
             speed > 0 ? "x" : " (full)", watch_n);
    for (int i = 0; i < watch_n; i++)
        fprintf (st, "%s%06o=%06o", i ? " " : ": ", watch[i], M[watch[i] >> 1]);
    return SCPE_OK;
}

static t_stat lab_show_panel (FILE *st, UNIT *uptr, int32 val, void *desc)
{
    fprintf (st, "PC=%06o PSW=%06o", (int) (R[7] & 0177777), (int) (get_PSW () & 0177777));
    for (int i = 0; i < 7; i++)
        fprintf (st, " R%d=%06o", i, (int) (R[i] & 0177777));
    fputc ('\n', st);
    if (out ()) {
        write_panel ();
        flush_all ();
    }
    return SCPE_OK;
}

static t_stat lab_show_interrupts (FILE *st, UNIT *uptr, int32 val, void *desc)
{
    fprintf (st, "interrupts taken (vector=count):");
    interrupt_count_write (st, " ");
    fputc ('\n', st);
    return SCPE_OK;
}

static t_stat lab_set_iobreak (UNIT *uptr, int32 val, char *cptr, void *desc)
{
    return val ? io_break_set (cptr) : io_break_clear ();
}

static t_stat lab_show_iobreak (FILE *st, UNIT *uptr, int32 val, void *desc)
{
    io_break_show (st);
    fputc ('\n', st);
    return SCPE_OK;
}
