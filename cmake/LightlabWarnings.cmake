# The warnings of every LightLab target (and of the task modules the autograder builds):
# one interface target, every flag explained. LIGHTLAB_WARNINGS_AS_ERRORS turns them into errors.
add_library(lightlab_warnings INTERFACE)
target_compile_options(lightlab_warnings INTERFACE
  -Wall                 # the common set of likely mistakes
  -Wextra               # unused parameters, sign/enum mismatches in comparisons, ...
  -Wpedantic            # stay within ISO C++20
  -Wshadow              # a local hiding a member or outer variable is a classic renderer bug
  -Wnon-virtual-dtor    # interfaces (Technique, Accelerator) are deleted through base pointers
  -Wold-style-cast      # casts should say what they do
  -Wcast-align          # misaligned loads of packed node arrays
  -Woverloaded-virtual  # a technique that fails to override because of a signature typo
  -Wdouble-promotion    # silent float->double promotion in hot loops costs speed
  -Wimplicit-fallthrough # switch cases must say [[fallthrough]]
  $<$<CXX_COMPILER_ID:GNU>:-Wno-restrict>  # GCC 12 false positive in std::string operator+ (GCC bug 105329)
  # Clang's -Wdouble-promotion also flags the deliberate `const double x = f;`; GCC (the main build) checks the rest.
  $<$<CXX_COMPILER_ID:Clang>:-Wno-double-promotion>
)
if(LIGHTLAB_WARNINGS_AS_ERRORS)
  target_compile_options(lightlab_warnings INTERFACE -Werror)  # CI: a warning fails the build
endif()
