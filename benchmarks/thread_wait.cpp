// What a second thread gains on this machine, and what each thread waits on: a bonded-disc step
// on arrays (the work of the disc path without YADE: pairs of a triangular lattice, forces summed
// per thread, then a 2D leapfrog), run on 1 and 2 OpenMP threads. Per thread it times its share
// of the pair loop and of the integration and the wait at each loop's closing barrier; with no
// work at all, the cost of a parallel region; and a loop of arithmetic on registers (no memory).
// If two threads each take as long for half the pairs as one thread takes for all of them, they
// wait on what they share (the memory system), not on each other.
//
//   g++ -O3 -march=native -fopenmp benchmarks/thread_wait.cpp -o /tmp/thread_wait && /tmp/thread_wait
//
// Prints one table (docs/performance.md, "Two threads").
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <omp.h>
#include <vector>

namespace {

struct Pair {
	int    i, j;
	double shear, bondShear, moment, rest;
};

struct Lattice {
	int                 n;
	std::vector<double> x, y, vx, vy, w, r, m;
	std::vector<Pair>   pairs;
	explicit Lattice(int side)
	        : n(side * side)
	        , x(n), y(n), vx(n), vy(n), w(n), r(n, 1e-3), m(n, 1e-2)
	{
		for (int row = 0; row < side; ++row)
			for (int col = 0; col < side; ++col) {
				const int k = row * side + col;
				x[k]        = 2e-3 * col + (row % 2 ? 1e-3 : 0);
				y[k]        = std::sqrt(3.0) * 1e-3 * row;
			}
		for (int a = 0; a < n; ++a)
			for (int b : { a + 1, a + side - 1, a + side, a + side + 1 })
				if (b < n && std::hypot(x[b] - x[a], y[b] - y[a]) < 2.2e-3)
					pairs.push_back({ a, b, 0, 0, 0, 2e-3 - std::hypot(x[b] - x[a], y[b] - y[a]) });
	}
};

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

struct Times {
	double wall = 0, pairs = 0, pairWait = 0, motion = 0, motionWait = 0;
};

// One step of the lattice on `threads` threads, `steps` times; per-thread times summed over steps
// and averaged over threads.
Times run(Lattice& L, int threads, int steps)
{
	const double dt = 1e-6, kn = 1e6, ks = 5e5, damping = 0.2;
	std::vector<std::vector<double>> fx(threads, std::vector<double>(L.n)), fy(fx), tq(fx);
	std::vector<Times>               per(threads);
	const auto                       start = Clock::now();
	for (int s = 0; s < steps; ++s) {
#pragma omp parallel num_threads(threads)
		{
			const int t  = omp_get_thread_num();
			auto &    FX = fx[t], &FY = fy[t], &TQ = tq[t];
			std::fill(FX.begin(), FX.end(), 0.0);
			std::fill(FY.begin(), FY.end(), 0.0);
			std::fill(TQ.begin(), TQ.end(), 0.0);
			const auto t0 = Clock::now();
#pragma omp for schedule(static) nowait
			for (size_t k = 0; k < L.pairs.size(); ++k) {
				Pair&        p = L.pairs[k];
				const int    a = p.i, b = p.j;
				const double dx = L.x[b] - L.x[a], dy = L.y[b] - L.y[a], d = std::sqrt(dx * dx + dy * dy);
				const double nx = dx / d, ny = dy / d, un = L.r[a] + L.r[b] - d;
				const double vs = (L.vx[b] - L.vx[a]) * -ny + (L.vy[b] - L.vy[a]) * nx - (L.w[a] * L.r[a] + L.w[b] * L.r[b]);
				p.shear -= ks * vs * dt;
				p.bondShear -= ks * vs * dt;
				p.moment -= kn * 1e-6 * (L.w[b] - L.w[a]) * dt;
				const double fn = kn * (un - p.rest) + (un > 0 ? kn * un : 0), fs = p.shear + p.bondShear;
				const double Fx = -fn * nx - fs * ny, Fy = -fn * ny + fs * nx;
				FX[b] += Fx;
				FY[b] += Fy;
				FX[a] -= Fx;
				FY[a] -= Fy;
				TQ[a] += fs * L.r[a] - p.moment;
				TQ[b] += fs * L.r[b] + p.moment;
			}
			const auto t1 = Clock::now();
#pragma omp barrier
			const auto t2 = Clock::now();
#pragma omp for schedule(static) nowait
			for (int k = 0; k < L.n; ++k) {
				double F[3] = { 0, 0, 0 };
				for (int q = 0; q < threads; ++q) {
					F[0] += fx[q][k];
					F[1] += fy[q][k];
					F[2] += tq[q][k];
				}
				F[1] -= 9.81 * L.m[k];
				for (double& f : F)
					f *= 1 - damping;
				L.vx[k] += dt * F[0] / L.m[k];
				L.vy[k] += dt * F[1] / L.m[k];
				L.w[k] += dt * F[2] / (0.5 * L.m[k] * L.r[k] * L.r[k]);
				L.x[k] += dt * L.vx[k];
				L.y[k] += dt * L.vy[k];
			}
			const auto t3 = Clock::now();
#pragma omp barrier
			const auto t4 = Clock::now();
			per[t].pairs += seconds(t0, t1);
			per[t].pairWait += seconds(t1, t2);
			per[t].motion += seconds(t2, t3);
			per[t].motionWait += seconds(t3, t4);
		}
	}
	Times mean;
	mean.wall = seconds(start, Clock::now()) / steps;
	for (const auto& p : per) {
		mean.pairs += p.pairs / steps / threads;
		mean.pairWait += p.pairWait / steps / threads;
		mean.motion += p.motion / steps / threads;
		mean.motionWait += p.motionWait / steps / threads;
	}
	return mean;
}

double emptyRegion(int threads, int repeats)
{
	const auto start = Clock::now();
	for (int s = 0; s < repeats; ++s) {
#pragma omp parallel num_threads(threads)
		{
#pragma omp barrier
		}
	}
	return seconds(start, Clock::now()) / repeats;
}

// Multiply-adds on registers: no memory traffic at all. Returns operations per second.
double arithmetic(int threads)
{
	const long per = 200000000;
	double     sink = 0;
	const auto start = Clock::now();
#pragma omp parallel num_threads(threads) reduction(+ : sink)
	{
		double a = 1.0 + omp_get_thread_num() * 1e-9, b = 0.999999;
		for (long k = 0; k < per; ++k)
			a = a * b + 1e-9;
		sink += a;
	}
	const double s = seconds(start, Clock::now());
	return sink > 0 ? threads * per / s : 0;
}

} // namespace

int main()
{
	Lattice L(141); // 19,881 discs, as benchmarks/laws.py
	const int steps = 400;
	run(L, 1, 20); // warm up
	std::printf("| threads | ns per pair-step | pair loop, per thread (us) | its wait (us) | motion, per thread (us) | its wait (us) | "
	            "empty parallel region (us) | arithmetic (Gop/s) |\n|---|---|---|---|---|---|---|---|\n");
	for (int threads : { 1, 2 }) {
		double best = 1e9;
		Times  kept;
		for (int repeat = 0; repeat < 3; ++repeat) { // the least disturbed of three
			const Times t = run(L, threads, steps);
			if (t.wall < best) {
				best = t.wall;
				kept = t;
			}
		}
		std::printf("| %d | %.1f | %.0f | %.0f | %.0f | %.0f | %.1f | %.2f |\n", threads, 1e9 * kept.wall / L.pairs.size(), 1e6 * kept.pairs,
		            1e6 * kept.pairWait, 1e6 * kept.motion, 1e6 * kept.motionWait, 1e6 * emptyRegion(threads, 20000),
		            1e-9 * arithmetic(threads));
	}
	std::printf("(%d discs, %zu bonded pairs, %d steps; OMP_PROC_BIND=%s)\n", L.n, L.pairs.size(), steps,
	            std::getenv("OMP_PROC_BIND") ? std::getenv("OMP_PROC_BIND") : "unset");
}
