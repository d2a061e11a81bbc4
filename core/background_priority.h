#pragma once
// Work that runs beside the window (lookup-table and environment bakes, file reads, the reference
// view's integration) yields the cores to the window's renders: on a machine of few cores a bake
// that takes every core would otherwise make the frame the user is waiting for take twice as long.
namespace aniso
{
// Lowers the calling thread's scheduling priority to a nice value of kBackgroundNice (Linux: per
// thread, and inherited by the threads it starts afterwards, as the bakes' parallel loops do).
// It still runs whenever a core is free, and takes about a tenth of a core it has to share. Once
// lowered it stays so (an unprivileged thread cannot raise it again): call it only on threads
// that run background work alone, such as a pool's workers. Does nothing where unsupported.
constexpr int kBackgroundNice = 10;
void lowerThreadPriority();
} // namespace aniso
