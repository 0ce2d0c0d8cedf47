// An object of the original Thyrix pushing itself in controll(): with THYRIX_OLD_NAME it must
// not compile (the method would never be called), and the error names control().
#include <ThyrixLite/Circle.h>

namespace {

class Seeker : public thyrix::Circle {
 public:
  Seeker() : Circle(thyrix::real(0.2), thyrix::real(1)) {}
#ifdef THYRIX_OLD_NAME
  void controll() { externalForce += thyrix::Vector2{1, 0}; }
#else
  void control() override { externalForce += thyrix::Vector2{1, 0}; }
#endif
};

}  // namespace

thyrix::Circle* makeSeeker() { return new Seeker; }  // NOLINT(cppcoreguidelines-owning-memory)
