// The benchmark problem of bench/compare_scipy.sh with Boost.Odeint: a
// seconds pendulum released at 3 degrees, Q = 1e6, every turning point
// located. Two steppers:
//   dopri5: controlled runge_kutta_dopri5 with dense output; a sign change of
//           theta' between steps is bisected on the dense output;
//   rkf78:  controlled runge_kutta_fehlberg78 (no dense output); a sign change
//           is bisected by re-stepping from the step's start.
// Prints: method, tolerance, steps, turning points, final amplitude.
// Build: g++ -O3 -march=x86-64 -o boost_pendulum boost_pendulum.cpp
// Usage: boost_pendulum dopri5|rkf78 TOL DURATION
#include <array>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

using namespace boost::numeric::odeint;
typedef std::array<double, 2> state;

static const double L = 0.99362, G = 9.80665;
static const double W = std::sqrt(G / L);
static const double C = 2.0 * (1.0 / (2.0 * 1e6)) * W;

struct Pendulum {
    void operator()(const state &y, state &dy, double) const {
        dy[0] = y[1];
        dy[1] = -C * y[1] - W * W * std::sin(y[0]);
    }
};

static double amplitude(const state &y) {
    double s = std::sin(0.5 * y[0]), v = y[1] / (2.0 * W);
    return 2.0 * std::asin(std::fmin(1.0, std::sqrt(s * s + v * v)));
}

int main(int argc, char **argv) {
    if (argc != 4) return 2;
    std::string method = argv[1];
    double tol = std::atof(argv[2]), duration = std::atof(argv[3]);
    state y = {3.0 * M_PI / 180.0, 0.0};
    long steps = 0, turns = 0;
    double last_angle = y[0];
    Pendulum sys;
    if (method == "dopri5") {
        auto stepper = make_dense_output(tol, tol, runge_kutta_dopri5<state>());
        stepper.initialize(y, 0.0, 1e-3);
        while (stepper.current_time() < duration) {
            stepper.do_step(sys);
            ++steps;
            double v0 = stepper.previous_state()[1], v1 = stepper.current_state()[1];
            if (v0 != 0.0 && (v0 < 0.0) != (v1 < 0.0)) {
                double a = stepper.previous_time(), b = stepper.current_time();
                state x;
                for (int i = 0; i < 100 && b - a > 1e-15 * b; ++i) {
                    double m = 0.5 * (a + b);
                    stepper.calc_state(m, x);
                    if ((x[1] < 0.0) == (v0 < 0.0)) a = m; else b = m;
                }
                stepper.calc_state(0.5 * (a + b), x);
                if (0.5 * (a + b) <= duration) { ++turns; last_angle = x[0]; }
            }
        }
        stepper.calc_state(duration, y);
    } else {
        auto stepper = make_controlled(tol, tol, runge_kutta_fehlberg78<state>());
        runge_kutta_fehlberg78<state> plain;
        double t = 0.0, dt = 1e-3;
        while (t < duration) {
            if (t + dt > duration) dt = duration - t;
            state before = y;
            double t_before = t;
            if (stepper.try_step(sys, y, t, dt) != success) continue;
            ++steps;
            double v0 = before[1], v1 = y[1];
            if (v0 != 0.0 && (v0 < 0.0) != (v1 < 0.0)) {
                double a = 0.0, b = t - t_before;
                state x;
                for (int i = 0; i < 100 && b - a > 1e-15 * t; ++i) {
                    double m = 0.5 * (a + b);
                    plain.do_step(sys, before, t_before, x, m);
                    if ((x[1] < 0.0) == (v0 < 0.0)) a = m; else b = m;
                }
                plain.do_step(sys, before, t_before, x, 0.5 * (a + b));
                ++turns;
                last_angle = x[0];
            }
        }
    }
    std::printf("%s %.0e %ld %ld %.17g %.17g\n", method.c_str(), tol, steps, turns, amplitude(y), last_angle);
    return 0;
}
