/*
 * glr: the OSMesa plugin's loader refuses, with the reason, a process
 * that may not make memory executable, before llvmpipe would fail inside
 * LLVM. The refusal is made real with a seccomp filter of the test's own
 * in a child process, the rule of systemd's MemoryDenyWriteExecute=yes
 * for mprotect: PROT_EXEC is refused with EPERM. The plugin loading
 * itself, and llvmpipe drawing under the unit with the drop-in that
 * allows it, are checked by check_install.sh and the VM tests.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <errno.h>
#include <linux/filter.h>
#include <linux/seccomp.h>
#include <stddef.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include "app/glr.h"

/* mprotect with PROT_EXEC in its third argument fails with EPERM; every
 * other call is allowed. */
static int deny_exec(void)
{
	struct sock_filter f[] = {
		BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(struct seccomp_data, nr)),
		BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, __NR_mprotect, 0, 3),
		BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(struct seccomp_data, args[2])),
		BPF_JUMP(BPF_JMP | BPF_JSET | BPF_K, PROT_EXEC, 0, 1),
		BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ERRNO | (EPERM & SECCOMP_RET_DATA)),
		BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ALLOW),
	};
	struct sock_fprog prog = { .len = (unsigned short)(sizeof(f) / sizeof(f[0])), .filter = f };

	if (prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0)
		return -1;
	return prctl(PR_SET_SECCOMP, SECCOMP_MODE_FILTER, &prog) == 0 ? 0 : -1;
}

static void a_normal_process_may_jit(void **state)
{
	(void)state;
	assert_int_equal(glr_can_jit(), 0);
}

/* In a child: 0 when the loader refused as it must, else a code saying
 * which part did not hold. */
static int child_checks(void)
{
	struct glr g;
	char why[512] = "";

	if (deny_exec() != 0)
		return 10;
	if (glr_can_jit() != -EPERM)
		return 11;
	if (glr_load(&g, why, sizeof(why)) != -EPERM)
		return 12;
	if (g.so)
		return 13;
	if (!strstr(why, "MemoryDenyWriteExecute=yes") || !strstr(why, "llvmpipe") ||
	    !strstr(why, strerror(EPERM)) || !strstr(why, "docs/systemd.md"))
		return 14;
	return 0;
}

static void memory_deny_write_execute_is_refused_with_the_reason(void **state)
{
	int status;
	pid_t pid;

	(void)state;
	pid = fork();
	assert_true(pid >= 0);
	if (pid == 0)
		_exit(child_checks());
	assert_int_equal(waitpid(pid, &status, 0), pid);
	assert_true(WIFEXITED(status));
	assert_int_equal(WEXITSTATUS(status), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(a_normal_process_may_jit),
		cmocka_unit_test(memory_deny_write_execute_is_refused_with_the_reason),
	};

	return cmocka_run_group_tests_name("glr", tests, NULL, NULL);
}
