// The pause instruction of a spin-wait loop: tells the core the thread is spinning (saves power,
// frees the sibling hyper-thread, avoids a memory-order mis-speculation when the wait ends).
#pragma once

namespace colav {

inline void CpuRelax() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#elif defined(__aarch64__)
  asm volatile("yield");
#endif
}

}  // namespace colav
