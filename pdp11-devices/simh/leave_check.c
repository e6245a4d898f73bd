/* leave_check.c: every way out of SIMH writes the FORTH's blocks first.

   Why: the FORTH keeps changed blocks (UPDATE) in its buffers until FLUSH.
   SIMH's QUIT, EXIT and BYE end the simulator at once, so a user who typed
   one at sim> lost them, however the command got there: typed, edited with
   the terminal's ^W/^U/^R/backspace, abbreviated (Q, EXI, BY), or read from
   a DO file. Watching keystrokes outside the simulator cannot see the
   terminal's own line editing; this check sits where every path meets.

   How: scp.c consults `sim_vm_cmd` before its own command table, matching
   the typed word as a prefix of each name in order. This table therefore
   holds EXIT, QUIT and BYE, and, before them, the stock commands SIMH would
   have chosen for the shorter words that are also prefixes of those names
   (E and EX are EXAMINE, B is BOOT), passed on to SIMH unchanged; and LOAD,
   passed on too, which notes the kernel a LOAD brings (FILE.lda, whose
   symbol map FILE.map lies beside it, as build/kernel.lda's does).

   At QUIT, EXIT or BYE the FORTH's buffer tables (BUF-BLK, BUF-UPD:
   forth/kernel/disk.fs) are read from memory. No block UPDATEd: SIMH quits
   as before, saying nothing (scripted runs print the same). Otherwise the CPU
   is started at the kernel's LEAVE-ENTRY (forth/kernel/boot.fs: fresh stacks,
   FLUSH under CATCH, then (BYE)'s HALT) for at most LEAVE_LIMIT_S simulated
   seconds, whatever the machine was doing when it stopped; then the tables
   are read again.
     all written      one line names them and the image; SIMH quits.
     some not         the way out is refused in one line naming the blocks and
                      how to leave anyway (QUIT -F); the machine stays at sim>
                      (CONT returns to the FORTH's prompt, where FLUSH can be
                      tried again once the disk is writable).
   QUIT -F (EXIT -F, BYE -F) leaves without them, saying which, with exit
   status 1. A memory that does not hold the noted kernel (another program
   loaded, no LOAD at all) is left as SIMH would. */
#include <string.h>
#include <strings.h>
#include "devices.h"

extern CTAB *sim_vm_cmd;
extern uint16 *M;
extern UNIT cpu_unit;                   /* MEMSIZE is its capacity */
t_stat sim_instr (void);
extern int32 saved_PC, PSW;
extern int32 sim_is_running;
extern volatile int32 stop_cpu;
extern int32 wait_state;               /* pdp11_cpu.c: the CPU is in WAIT */
extern char *sim_stop_messages[];
extern DEVICE rl_dev;
t_stat detach_all (int32 start_device, t_bool shutdown);

#define NAME_MAX_LEN 40
#define BUFS 4                          /* forth/kernel/disk.fs #BUFS */
#define BODY 4                          /* a CREATEd word's data: code field + 4 */
#define NO_BLOCK 0177777
#define MTPS_IMMEDIATE 0106427          /* LEAVE-ENTRY's first instruction: MTPS #n */
#define LEAVE_LIMIT_S 2                 /* simulated seconds FLUSH may take */
#define LEFT_WITHOUT_BLOCKS 1           /* exit status of QUIT -F that lost blocks */
#define LIST_MAX 200

enum { WAY_EXIT, WAY_QUIT, WAY_BYE, STOCK_EXAMINE, STOCK_BOOT, STOCK_LOAD };
static const char *names[] = { "EXIT", "QUIT", "BYE", "EXAMINE", "BOOT", "LOAD" };

static struct {                         /* the kernel the last LOAD brought, from its map */
    int known;
    uint32 entry, bye, buf_blk, buf_upd;
} kernel;

static t_stat leave_cmd (int32 way, char *cptr);
static t_stat stock_cmd (int32 which, char *cptr);

/* stock commands first: see the header for why the order matters */
static CTAB leave_table[] = {
    { "EXAMINE", &stock_cmd, STOCK_EXAMINE, NULL },
    { "BOOT", &stock_cmd, STOCK_BOOT, NULL },
    { "LOAD", &stock_cmd, STOCK_LOAD, NULL },
    { "EXIT", &leave_cmd, WAY_EXIT, NULL },
    { "QUIT", &leave_cmd, WAY_QUIT, NULL },
    { "BYE", &leave_cmd, WAY_BYE, NULL },
    { NULL, NULL, 0, NULL }
};

static CTAB *stock_entry (const char *name)
{
    CTAB *saved = sim_vm_cmd, *found;
    char word[NAME_MAX_LEN];
    strcpy (word, name);
    sim_vm_cmd = NULL;
    found = find_cmd (word);
    sim_vm_cmd = saved;
    return found;
}

/* ---- the kernel: its symbols from FILE.map --------------------------------- */
static void note_kernel (const char *lda)
{
    char map[CBUFSIZE], name[NAME_MAX_LEN + 1], line[CBUFSIZE];
    size_t n = strlen (lda);
    unsigned int addr;
    int found = 0;
    FILE *f;
    kernel.known = 0;
    if (n < 4 || n >= sizeof map || strcasecmp (lda + n - 4, ".lda") != 0)
        return;
    strcpy (map, lda);
    strcpy (map + n - 4, ".map");
    if ((f = fopen (map, "r")) == NULL)
        return;
    while (fgets (line, sizeof line, f) != NULL) {
        if (sscanf (line, "%o %40s", &addr, name) != 2)
            continue;
        if (strcmp (name, "LEAVE-ENTRY") == 0)
            kernel.entry = addr, found |= 1;
        else if (strcmp (name, "(BYE)") == 0)
            kernel.bye = addr, found |= 2;
        else if (strcmp (name, "BUF-BLK") == 0)
            kernel.buf_blk = addr + BODY, found |= 4;
        else if (strcmp (name, "BUF-UPD") == 0)
            kernel.buf_upd = addr + BODY, found |= 8;
    }
    fclose (f);
    kernel.known = found == 15;
}

static uint32 word_at (uint32 addr)
{
    return addr < MEMSIZE ? M[addr >> 1] : 0;
}

/* The kernel is in memory as its map says: LEAVE-ENTRY and (BYE)'s HALT there. */
static int kernel_present (void)
{
    return kernel.known && word_at (kernel.entry) == MTPS_IMMEDIATE
        && word_at (kernel.bye) == 0;
}

/* The UPDATEd blocks, listed "300, 301" into `list`; how many. */
static int updated_blocks (char *list, size_t n)
{
    int count = 0;
    size_t used = 0;
    list[0] = 0;
    for (int i = 0; i < BUFS; i++) {
        uint32 blk = word_at (kernel.buf_blk + 2 * i);
        if (word_at (kernel.buf_upd + 2 * i) == 0 || blk == NO_BLOCK)
            continue;
        used += snprintf (list + used, used < n ? n - used : 0, "%s%u",
                          count ? ", " : "", (unsigned) blk);
        count++;
    }
    return count;
}

/* ---- running the kernel's FLUSH --------------------------------------------- */
static t_stat limit_svc (UNIT *uptr)
{
    return SCPE_STOP;
}

static UNIT limit_unit = { UDATA (&limit_svc, 0, 0) };

/* Run LEAVE-ENTRY to (BYE)'s HALT; "" when it got there, else why not. */
static const char *run_flush (void)
{
    static char why[CBUFSIZE];
    t_stat r;
    saved_PC = kernel.entry;
    PSW = 0340;                         /* kernel mode, priority 7: the entry lowers it */
    wait_state = 0;                     /* stopped in KEY's WAIT: start afresh */
    sim_activate (&limit_unit, LEAVE_LIMIT_S * clock_rate);
    stop_cpu = 0;                       /* as RUN and CONT do */
    sim_ttrun ();
    sim_is_running = 1;
    r = sim_instr ();
    sim_is_running = 0;
    sim_ttcmd ();
    sim_cancel (&limit_unit);
    if (r == STOP_HALT && (uint32) saved_PC == kernel.bye + 2)
        return "";
    if (r == SCPE_STOP)
        snprintf (why, sizeof why, "FLUSH did not end within %d simulated seconds",
                  LEAVE_LIMIT_S);
    else
        snprintf (why, sizeof why, "the machine stopped (%s, PC: %06o)",
                  r < SCPE_BASE && sim_stop_messages[r] ? sim_stop_messages[r] : "stop",
                  saved_PC);
    return why;
}

static int forced (const char *cptr)
{
    char word[CBUFSIZE];
    while (*cptr) {
        cptr = get_glyph ((char *) cptr, word, 0);
        if (strcmp (word, "-F") == 0)
            return 1;
    }
    return 0;
}

/* ---- the commands ---------------------------------------------------------- */
static t_stat leave_cmd (int32 way, char *cptr)
{
    char before[LIST_MAX], after[LIST_MAX];
    const char *name = names[way], *why, *disk = rl_dev.units[0].filename;
    if (!kernel_present () || updated_blocks (before, sizeof before) == 0)
        return SCPE_EXIT;
    why = run_flush ();
    if (updated_blocks (after, sizeof after) == 0) {
        printf ("%s: the FORTH's UPDATEd block(s) %s were written to %s first\n",
                name, before, disk ? disk : "RL0");
        return SCPE_EXIT;
    }
    if (forced (cptr)) {
        printf ("%s -F: leaving without block(s) %s: UPDATEd, NOT SAVED\n", name, after);
        fflush (stdout);
        detach_all (0, TRUE);
        sim_ttclose ();
        exit (LEFT_WITHOUT_BLOCKS);
    }
    printf ("%s refused: block(s) %s UPDATEd and not written (%s); CONT, make the disk "
            "writable and FLUSH, or %s -F to leave without them\n", name, after,
            *why ? why : "the write failed, see above", name);
    return SCPE_OK;
}

static t_stat stock_cmd (int32 which, char *cptr)
{
    char args[CBUFSIZE], file[CBUFSIZE];
    const char *rest = args;
    t_stat r;
    strncpy (args, cptr, sizeof args - 1);
    args[sizeof args - 1] = 0;
    r = stock_entry (names[which])->action (stock_entry (names[which])->arg, cptr);
    if (which != STOCK_LOAD || r != SCPE_OK)
        return r;
    do                                  /* the file name follows the switches */
        rest = get_glyph_nc ((char *) rest, file, 0);
    while (file[0] == '-' && *rest);
    note_kernel (file);
    return r;
}

void leave_check_install (void)
{
    for (CTAB *c = leave_table; c->name != NULL; c++)
        c->help = stock_entry (c->name)->help;   /* HELP lists them as before */
    sim_vm_cmd = leave_table;
}
