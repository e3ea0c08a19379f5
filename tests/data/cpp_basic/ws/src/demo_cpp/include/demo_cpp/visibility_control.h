#ifndef DEMO_CPP__VISIBILITY_CONTROL_H_
#define DEMO_CPP__VISIBILITY_CONTROL_H_

#if defined _WIN32 || defined __CYGWIN__
  #define DEMO_CPP_PUBLIC __declspec(dllexport)
#else
  #define DEMO_CPP_PUBLIC __attribute__ ((visibility("default")))
#endif

#endif  // DEMO_CPP__VISIBILITY_CONTROL_H_
