// orni_peak_rss FILE COMMAND [ARGS...]: runs COMMAND, writes its peak resident set size in KiB to
// FILE (getrusage semantics of wait4: the largest of the command and of every descendant it
// waited for, gnuplot included) and exits with the command's status (128 + signal when it was
// killed). Used by tests/regression/memory_bounded.sh.
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: orni_peak_rss FILE COMMAND [ARGS...]\n");
    return 2;
  }
  const pid_t pid = ::fork();
  if (pid < 0) {
    std::fprintf(stderr, "orni_peak_rss: fork: %s\n", std::strerror(errno));
    return 2;
  }
  if (pid == 0) {
    ::execvp(argv[2], argv + 2);
    std::fprintf(stderr, "orni_peak_rss: cannot run %s: %s\n", argv[2], std::strerror(errno));
    ::_exit(127);
  }
  int status = 0;
  struct rusage usage {};
  while (::wait4(pid, &status, 0, &usage) < 0) {
    if (errno != EINTR) {
      std::fprintf(stderr, "orni_peak_rss: wait4: %s\n", std::strerror(errno));
      return 2;
    }
  }
  std::FILE* f = std::fopen(argv[1], "w");
  if (!f || std::fprintf(f, "%ld\n", usage.ru_maxrss) < 0 || std::fclose(f) != 0) {
    std::fprintf(stderr, "orni_peak_rss: cannot write %s\n", argv[1]);
    return 2;
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return 2;
}
