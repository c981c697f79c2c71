/* sigaltstack shim for libFuzzer runs (fuzz/campaign.sh preloads it; see fuzz/README.md). A stack overflow
 * under libFuzzer is silent: its SIGSEGV handler runs on the overflowed stack and the input is lost. This
 * installs a 4 MiB alternate signal stack and a SIGSEGV handler on it that raises SIGABRT, whose libFuzzer
 * handler then writes the crashing input. Build: cc -shared -fPIC -O2 -o altstack.so altstack.c */
#define _GNU_SOURCE
#include <signal.h>
#include <stdlib.h>
#include <unistd.h>
static void on_segv(int sig, siginfo_t *si, void *uc) {
    (void)sig; (void)si; (void)uc;
    static const char m[] = "altstack: SIGSEGV (stack overflow?), raising SIGABRT for libFuzzer\n";
    write(2, m, sizeof m - 1);
    raise(SIGABRT);
    _exit(99);
}
__attribute__((constructor)) static void init(void) {
    stack_t ss;
    ss.ss_sp = malloc(1 << 22);
    ss.ss_size = 1 << 22;
    ss.ss_flags = 0;
    sigaltstack(&ss, 0);
    struct sigaction sa = {0};
    sa.sa_flags = SA_SIGINFO | SA_ONSTACK;
    sa.sa_sigaction = on_segv;
    sigaction(SIGSEGV, &sa, 0);
}
