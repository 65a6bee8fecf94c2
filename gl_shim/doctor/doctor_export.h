/* The one function libGL.so.1 exports beside the GL, GLX and EGL API: `glpt doctor` dlopens
   the library `glpt run` would preload and calls it (gl_shim/doctor/doctor_export.cpp). */
#pragma once

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Writes the text encoding of the library's Vulkan device survey (common/device_survey.hpp)
   into buffer, at most size bytes including the terminating NUL, and returns the length of the
   whole encoding without the NUL (snprintf's convention: call again with a larger buffer when
   the result is >= size). Returns 0 when the survey itself failed (out of memory).
   GLPT_VK_DEVICE and GLPT_VK_NO_RAY_QUERY count as for a renderer. */
__attribute__((visibility("default"))) size_t glpt_doctor_survey(char* buffer, size_t size);
typedef size_t (*glpt_doctor_survey_function)(char* buffer, size_t size);

#ifdef __cplusplus
}
#endif
