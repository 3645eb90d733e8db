#pragma once
// OpenBLAS's own threads held at one while the library runs threads of its own
// (nodal diameters side by side): each of our threads calling a BLAS that starts
// threads of its own oversubscribes the cores. Measured on 2 cores with OpenBLAS's
// default of one thread per core: the modal benchmark's nodal diameters on 2 threads
// took 84.7 s against 44 s with OpenBLAS at one thread.

namespace cyclone {

/// While it lives, OpenBLAS (when it is the BLAS this process loaded) runs on one
/// thread; its former count is restored on destruction. Other BLAS libraries are left
/// alone. OpenBLAS's count is process-wide: make it on the thread that starts the others.
class SingleThreadedBlas {
public:
  SingleThreadedBlas();
  ~SingleThreadedBlas();
  SingleThreadedBlas(const SingleThreadedBlas&) = delete;
  SingleThreadedBlas& operator=(const SingleThreadedBlas&) = delete;

private:
  int restore_ = 0;  ///< the count to put back; 0: nothing was changed
};

}  // namespace cyclone
