/* The Linux system calls newlib needs, for a Cortex-M4F program run under qemu-arm's user
 * mode (shipped with rigidsym for the command of docs/c-api.md, "float and double"; used by
 * tests/test_c_target_arm.py): the bare-metal build's _read, _write, _exit and _sbrk as Linux
 * calls (svc 0, the number in r7), and a _start that qemu enters with no C runtime set up
 * beyond what the ELF loader does (.data loaded, .bss zeroed). SPDX-License-Identifier: MIT */
#include <errno.h>
#include <sys/stat.h>
#include <stdlib.h>

int main(void);
int _write(int fd, const void *buf, int len);
int _read(int fd, void *buf, int len);
void _exit(int status);
void *_sbrk(int inc);
int _fstat(int fd, struct stat *st);
int _isatty(int fd);

static int sys3(int n, int a, int b, int c)
{
    register int r0 __asm__("r0") = a;
    register int r1 __asm__("r1") = b;
    register int r2 __asm__("r2") = c;
    register int r7 __asm__("r7") = n;
    __asm__ volatile("svc #0" : "+r"(r0) : "r"(r1), "r"(r2), "r"(r7) : "memory");
    return r0;
}

int _write(int fd, const void *buf, int len) { return sys3(4, fd, (int)buf, len); }
int _read(int fd, void *buf, int len) { return sys3(3, fd, (int)buf, len); }
void _exit(int status) { sys3(1, status, 0, 0); for (;;) ; }
static char heap[1 << 16];
static char *brk_ = heap;
void *_sbrk(int inc)
{
    char *p = brk_;
    if (inc > heap + sizeof heap - brk_) { errno = ENOMEM; return (void *)-1; }
    brk_ += inc;
    return p;
}
int _fstat(int fd, struct stat *st) { (void)fd; st->st_mode = S_IFCHR; return 0; }
int _isatty(int fd) { (void)fd; return 1; }
void _start_c(void);
void _start_c(void) { exit(main()); }
__attribute__((naked, noreturn)) void _start(void);
__attribute__((naked, noreturn)) void _start(void) { __asm__ volatile("bl _start_c\n\tb .\n"); }
/* newlib's exit() runs _fini, which crti.o gives and -nostartfiles leaves out */
void _init(void);
void _fini(void);
void _init(void) {}
void _fini(void) {}
