#pragma once

// Functions that a CUDA build will also compile for the device; plain inline on the host.
#ifndef SPHCAST_HOST_DEVICE
#ifdef __CUDACC__
#define SPHCAST_HOST_DEVICE __host__ __device__
#else
#define SPHCAST_HOST_DEVICE
#endif
#endif
