"""The Python module on numpy arrays: a noisy sphere smoothed in memory, its
report, a morph's frames as a list or through a callback, files read and
written, errors as exceptions that name what is wrong, and the GIL released
while the device works."""
import os
import signal
import tempfile
import threading
import traceback
import unittest

import numpy as np

import lbmshape


def icosphere(subdivisions=4):
    """A unit icosphere, outward: (vertices, triangles)."""
    t = (1 + 5 ** 0.5) / 2
    v = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
         (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
         (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
         (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    v = [np.array(p, float) / np.linalg.norm(p) for p in v]
    for _ in range(subdivisions):
        middle, finer = {}, []

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                m = v[a] + v[b]
                v.append(m / np.linalg.norm(m))
                middle[key] = len(v) - 1
            return middle[key]

        for a, b, c in f:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            finer += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
        f = finer
    return np.array(v), np.array(f, dtype=np.int64)


def noisy_sphere():
    v, f = icosphere()
    rng = np.random.default_rng(5)
    return v * (1 + 0.02 * rng.standard_normal((len(v), 1))), f


def closed(f):
    """Every edge in exactly two triangles."""
    edges = np.sort(np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]]), axis=1)
    _, counts = np.unique(edges, axis=0, return_counts=True)
    return bool(np.all(counts == 2))


class Denoise(unittest.TestCase):
    def test_a_noisy_sphere_comes_back_closed_and_rounder(self):
        v, f = noisy_sphere()
        v2, f2 = lbmshape.denoise(v, f, res=48)
        self.assertEqual(v2.shape[1], 3)
        self.assertEqual(f2.shape[1], 3)
        self.assertGreater(len(f2), 1000)
        self.assertTrue(closed(f2))
        before = np.abs(np.linalg.norm(v, axis=1) - 1).max()
        after = np.abs(np.linalg.norm(v2, axis=1) - 1).max()
        self.assertLess(after, before)

    def test_the_report_is_denoise_json(self):
        v, f = noisy_sphere()
        v2, f2, report = lbmshape.denoise(v, f, res=40, steps=3, report=True)
        self.assertEqual(report["steps"], 3)
        self.assertEqual(report["steps_chosen"], "given")
        self.assertEqual(report["smoothing"], "preserve-features")  # the default
        self.assertEqual(report["grid"]["size"], [40, 40, 40])
        self.assertIn("lbm", report["ms"])
        self.assertFalse(report["twicing"])  # given steps: plain unless told
        self.assertEqual(report["twicing_chosen"], "auto")
        self.assertEqual(report["relax_rounds"], 2)  # the default
        # The figures of the meshes, as denoise --json prints them.
        self.assertEqual(report["command"], "denoise")
        self.assertEqual(report["output"]["triangles"], len(f2))
        self.assertLess(abs(report["volume_change"]), 0.01)  # the volume kept
        _, _, twiced = lbmshape.denoise(v, f, res=40, steps=3, twicing=True, report=True)
        self.assertTrue(twiced["twicing"])
        self.assertEqual(twiced["twicing_chosen"], "given")
        _, _, plain = lbmshape.denoise(v, f, res=40, twicing=False, report=True)
        self.assertFalse(plain["twicing"])
        self.assertEqual(plain["twicing_chosen"], "given")
        self.assertEqual(twiced["steps_run"], report["steps_run"] + 3)
        _, _, by_radius = lbmshape.denoise(v, f, res=40, radius=0.1, report=True)
        self.assertEqual(by_radius["steps_chosen"], "radius")
        self.assertEqual(by_radius["radius"], 0.1)
        # A call's warnings are in its report, not only on stderr.
        self.assertEqual(report["warnings"], [])
        _, _, warned = lbmshape.denoise(v, f, res=40, gamma=1, steps=3, report=True)
        self.assertEqual(len(warned["warnings"]), 1)
        self.assertIn("smooths 61.8 % less than the diffusion equation", warned["warnings"][0])

    def test_the_distances_on_the_device_give_the_same_mesh(self):
        v, f = noisy_sphere()
        # relax=0: the two fields' meshes, compared vertex by vertex before
        # relaxation, whose guard against turning a triangle over may keep
        # a vertex in one and move it in the other.
        v_cpu, f_cpu, cpu = lbmshape.denoise(v, f, res=40, steps=3, relax=0, report=True,
                                             device=lbmshape.Device(sdf="cpu"))
        v_dev, f_dev, dev = lbmshape.denoise(v, f, res=40, steps=3, relax=0, report=True,
                                             device=lbmshape.Device(sdf="device"))
        self.assertEqual(cpu["relax_rounds"], 0)
        self.assertEqual(cpu["sdf_on"], "cpu")
        self.assertEqual(dev["sdf_on"], "device")
        self.assertEqual(f_cpu.shape, f_dev.shape)
        self.assertLess(np.abs(v_cpu - v_dev).max(), 0.05 * cpu["grid"]["voxel"])
        with self.assertRaisesRegex(ValueError, "^sdf must be 'auto', 'cpu' or 'device'"):
            lbmshape.Device(sdf="gpu")

    def test_a_device_name_that_matches_none_is_refused_where_it_is_given(self):
        with self.assertRaisesRegex(lbmshape.UsageError, "nosuchgpu matches no Vulkan device \\(have: 0: "):
            lbmshape.Device("nosuchgpu")
        self.assertEqual(lbmshape.Device("reference").name, "reference (CPU)")
        self.assertEqual(lbmshape.Device("0").name, lbmshape.Device().name)

    def test_every_error_is_an_lbmshape_error_and_a_builtin_one(self):
        for name, builtin in [("UsageError", ValueError), ("InputError", ValueError),
                              ("OutputError", OSError), ("DeviceError", RuntimeError)]:
            error = getattr(lbmshape, name)
            self.assertTrue(issubclass(error, lbmshape.Error), name)
            self.assertTrue(issubclass(error, builtin), name)
        v, f = noisy_sphere()
        with self.assertRaises(lbmshape.Error):
            lbmshape.denoise(v, f, gamma=-1)

    def test_bad_arrays_and_parameters_name_what_is_wrong(self):
        v, f = noisy_sphere()
        with self.assertRaisesRegex(lbmshape.UsageError, "vertices must be an array of shape"):
            lbmshape.denoise(v[:, :2], f)
        with self.assertRaisesRegex(ValueError, r"^triangles\[0\] has index \d+, but there are \d+ vertices$"):
            lbmshape.denoise(v, f + len(v))
        broken = v.copy()
        broken[3, 1] = np.nan
        with self.assertRaisesRegex(lbmshape.InputError, r"^vertices\[3\] has a coordinate that is not a finite"):
            lbmshape.denoise(broken, f)
        # A morph's two meshes are told apart.
        with self.assertRaisesRegex(ValueError, "^target_vertices must be an array of shape"):
            lbmshape.morph(v, f, v[:, :2], f)
        with self.assertRaisesRegex(ValueError, r"^source_triangles\[0\] has index .* source_vertices$"):
            lbmshape.morph(v, f + len(v), v, f)
        with self.assertRaisesRegex(ValueError, "^gamma must be a positive number"):
            lbmshape.denoise(v, f, gamma=-1)
        # The keyword, not the command line's flag (--res) or the C++ field.
        with self.assertRaisesRegex(ValueError, "^res 4 is too coarse for a margin of 4 voxels; use at least 12$"):
            lbmshape.denoise(v, f, res=4)
        with self.assertRaisesRegex(ValueError, "^cs must be a morphing speed"):
            lbmshape.morph(v, f, v, f, cs=2)
        with self.assertRaisesRegex(ValueError, "smoothing must be"):
            lbmshape.denoise(v, f, smoothing="gentle")
        with self.assertRaisesRegex(ValueError, "^radius and steps both say how much to smooth"):
            lbmshape.denoise(v, f, radius=0.1, steps=3)
        with self.assertRaisesRegex(ValueError, "^relax must be from 0 to 100$"):
            lbmshape.denoise(v, f, relax=-1)
        flat = v.copy()
        flat[:, 2] = 0
        with self.assertRaises(lbmshape.InputError):
            lbmshape.denoise(flat, f)

    def test_other_python_threads_run_while_the_device_works(self):
        v, f = noisy_sphere()
        ticks, done = [0], threading.Event()
        worker = threading.Thread(target=lambda: (lbmshape.denoise(v, f, res=64, steps=7), done.set()))
        worker.start()
        while not done.is_set():
            ticks[0] += 1
        worker.join()
        self.assertGreater(ticks[0], 1000, "the main thread was held while the device worked")

    def test_threads_calling_at_once_get_what_one_thread_gets(self):
        v, f = noisy_sphere()
        expected_v, expected_f = lbmshape.denoise(v, f, res=32)
        for device in [None, lbmshape.Device()]:  # each thread's own, then one they share
            results, failures = [None, None], []

            def call(i):
                try:
                    results[i] = lbmshape.denoise(v, f, res=32, device=device)
                except BaseException as e:
                    failures.append(e)

            threads = [threading.Thread(target=call, args=(i,)) for i in range(2)]
            for t in threads:
                t.start()
            for t in threads:
                t.join()
            self.assertEqual(failures, [])
            for got_v, got_f in results:
                np.testing.assert_array_equal(got_f, expected_f)
                np.testing.assert_array_equal(got_v, expected_v)

    def test_the_log_level_sets_what_the_calls_print(self):
        v, f = noisy_sphere()

        def stderr_of(call):
            with tempfile.TemporaryFile() as caught:
                saved = os.dup(2)
                os.dup2(caught.fileno(), 2)
                try:
                    call()
                finally:
                    os.dup2(saved, 2)
                    os.close(saved)
                caught.seek(0)
                return caught.read().decode()

        try:
            lbmshape.set_log_level("verbose")
            self.assertIn("lbmshape: sdf", stderr_of(lambda: lbmshape.denoise(v, f, res=24)))
            lbmshape.set_log_level("quiet")
            self.assertEqual(stderr_of(lambda: lbmshape.denoise(v, f, res=24)), "")
        finally:
            lbmshape.set_log_level("normal")
        with self.assertRaisesRegex(ValueError, "^level must be 'quiet', 'normal' or 'verbose', not 'loud'$"):
            lbmshape.set_log_level("loud")

    def test_a_log_handler_takes_the_messages_instead_of_stderr(self):
        v, f = noisy_sphere()
        said = []
        stderr_text = []

        def denoise_with_stderr_caught():
            with tempfile.TemporaryFile() as caught:
                saved = os.dup(2)
                os.dup2(caught.fileno(), 2)
                try:
                    lbmshape.denoise(v, f, res=24)
                finally:
                    os.dup2(saved, 2)
                    os.close(saved)
                caught.seek(0)
                stderr_text.append(caught.read().decode())

        try:
            lbmshape.set_log_level("verbose")
            lbmshape.set_log_handler(lambda kind, message: said.append((kind, message)))
            denoise_with_stderr_caught()
            lbmshape.set_log_handler(None)
            count = len(said)
            denoise_with_stderr_caught()
        finally:
            lbmshape.set_log_handler(None)
            lbmshape.set_log_level("normal")
        self.assertEqual(stderr_text[0], "")
        kinds = {kind for kind, _ in said}
        self.assertTrue(kinds <= {"info", "verbose", "warning", "progress"}, kinds)
        self.assertIn("verbose", kinds)
        self.assertTrue(any(message.startswith("sdf") for _, message in said), said)
        self.assertFalse(any(message.startswith("lbmshape:") for _, message in said), said)
        # None: stderr again, and the handler hears nothing more.
        self.assertEqual(len(said), count)
        self.assertIn("lbmshape: ", stderr_text[1])

    def test_a_log_handler_that_raises_leaves_the_call_going(self):
        import sys
        v, f = noisy_sphere()
        unraisable = []
        saved_hook = sys.unraisablehook
        sys.unraisablehook = lambda report: unraisable.append(report.exc_value)

        def refuse(kind, message):
            raise RuntimeError("no logs here")

        try:
            lbmshape.set_log_level("verbose")
            lbmshape.set_log_handler(refuse)
            v2, f2 = lbmshape.denoise(v, f, res=24)
        finally:
            lbmshape.set_log_handler(None)
            lbmshape.set_log_level("normal")
            sys.unraisablehook = saved_hook
        self.assertTrue(closed(f2))
        self.assertTrue(unraisable)
        self.assertTrue(all(isinstance(e, RuntimeError) for e in unraisable), unraisable)
        with self.assertRaisesRegex(TypeError, "^handler must be a function of \\(kind, message\\), or None, not int$"):
            lbmshape.set_log_handler(3)

    def test_triangles_must_be_integers_and_in_range(self):
        v, f = noisy_sphere()
        with self.assertRaisesRegex(lbmshape.UsageError, "^triangles must hold integers .*float64"):
            lbmshape.denoise(v, f + 0.9)
        with self.assertRaisesRegex(lbmshape.InputError, r"^triangles\[0\] has index"):
            lbmshape.denoise(v, f + len(v))
        v2, f2 = lbmshape.denoise(v, f.astype(np.uint32), res=24)  # any integer type
        self.assertTrue(closed(f2))
        self.assertTrue(issubclass(lbmshape.NumericalError, lbmshape.Error))
        self.assertTrue(issubclass(lbmshape.NumericalError, RuntimeError))


def ellipsoid():
    """The unit icosphere stretched along x: a shape a sphere can become."""
    v, f = icosphere(3)
    return v * np.array([1.4, 0.8, 0.8]), f


class Morph(unittest.TestCase):
    def test_the_frames_come_as_a_list_and_end_near_the_target(self):
        v, f = icosphere(3)
        vt, ft = ellipsoid()
        frames, report = lbmshape.morph(v, f, vt, ft, frames=5, res=32, align="none", report=True)
        self.assertEqual(len(frames), 5)
        for vk, fk in frames:
            self.assertEqual(vk.shape[1], 3)
            self.assertTrue(closed(fk))
        self.assertIsNone(report["folder"])
        self.assertLess(report["final"]["mean_distance_to_target_voxels"], 0.25)
        first_x = np.abs(frames[0][0][:, 0]).max()
        last_x = np.abs(frames[-1][0][:, 0]).max()
        self.assertGreater(last_x, first_x + 0.2, "the last frame is stretched as the target is")

    def test_the_command_lines_grid_and_schedule_options_are_keywords(self):
        v, f = icosphere(3)
        vt, ft = ellipsoid()
        frames, report = lbmshape.morph(v, f, vt, ft, frames=3, voxel=0.1, margin=3, align="none", report=True)
        self.assertAlmostEqual(report["grid"]["voxel"], 0.1)
        frames, paper = lbmshape.morph(v, f, vt, ft, frames=3, res=24, steps_per_frame=2, align="none", report=True)
        self.assertEqual(paper["steps"], 4)  # the paper's scheme: the steps given, 2 a frame
        _, loose = lbmshape.morph(v, f, vt, ft, frames=2, res=24, tolerance=1.0, align="none", report=True)
        _, tight = lbmshape.morph(v, f, vt, ft, frames=2, res=24, tolerance=0.1, align="none", report=True)
        self.assertLess(loose["steps"], tight["steps"], "a looser tolerance arrives sooner")
        _, noisy = lbmshape.morph(v, f, vt, ft, frames=2, res=24, noise=0.05, seed=3, align="none", report=True)
        self.assertEqual(noisy["lattice"]["kind"], "grid")  # the paper's noise is added on the grid
        with self.assertRaisesRegex(lbmshape.UsageError, "res or voxel, not both"):
            lbmshape.morph(v, f, vt, ft, res=24, voxel=0.1)
        with self.assertRaisesRegex(lbmshape.UsageError, "margin"):
            lbmshape.morph(v, f, vt, ft, res=24, margin=0)
        with self.assertRaisesRegex(lbmshape.UsageError, "tolerance"):
            lbmshape.morph(v, f, vt, ft, res=24, tolerance=5)
        _, _, smoothed = lbmshape.denoise(v, f, voxel=0.1, steps=1, report=True)
        self.assertAlmostEqual(smoothed["grid"]["voxel"], 0.1)

    def test_the_frames_extracted_on_the_device_are_the_cpus(self):
        v, f = icosphere(3)
        vt, ft = ellipsoid()
        runs = {}
        for where in ("cpu", "device"):
            runs[where] = lbmshape.morph(v, f, vt, ft, frames=3, res=24, align="none", report=True,
                                         device=lbmshape.Device(extract=where))
            self.assertEqual(runs[where][1]["extract_on"], where)
        for (v_cpu, f_cpu), (v_dev, f_dev) in zip(runs["cpu"][0], runs["device"][0]):
            np.testing.assert_array_equal(v_cpu, v_dev)
            np.testing.assert_array_equal(f_cpu, f_dev)
        self.assertEqual(runs["cpu"][1]["per_frame"], runs["device"][1]["per_frame"])
        with self.assertRaisesRegex(ValueError, "^extract must be 'auto', 'cpu' or 'device'"):
            lbmshape.Device(extract="gpu")

    def test_on_frame_sees_every_frame_in_order(self):
        v, f = icosphere(3)
        vt, ft = ellipsoid()
        seen = []
        result = lbmshape.morph(v, f, vt, ft, frames=4, res=24, steps=20, align="none",
                                on_frame=lambda k, vk, fk: seen.append((k, len(fk))))
        self.assertIsNone(result)
        self.assertEqual([k for k, _ in seen], [0, 1, 2, 3])
        self.assertTrue(all(n > 0 for _, n in seen))

    def test_an_error_in_on_frame_stops_the_morph_and_is_raised_as_it_was(self):
        v, f = icosphere(3)
        vt, ft = ellipsoid()

        class NoRoom(Exception):
            pass

        seen = []

        def refuse(k, vk, fk):
            seen.append(k)
            raise NoRoom("no room for frame %d" % k)

        try:
            lbmshape.morph(v, f, vt, ft, frames=4, res=24, steps=20, align="none", on_frame=refuse)
            self.fail("no exception")
        except NoRoom as e:  # not assertRaises, which drops the traceback
            self.assertEqual(str(e), "no room for frame 0")
            frames = traceback.extract_tb(e.__traceback__)
            self.assertEqual(frames[-1].name, "refuse", "the traceback reaches into the callback")
        self.assertEqual(seen, [0])
        with self.assertRaisesRegex(ValueError, "align must be"):
            lbmshape.morph(v, f, vt, ft, align="left")

    def frames_made_stopping_at_frame_1(self, stop, raises):
        """The frames a 24-frame morph gives when stop() is called from its
        frame 1, and the exception it raises, `raises`, checked."""
        v, f = icosphere(3)
        vt, ft = ellipsoid()
        seen = []

        def on_frame(k, vk, fk):
            seen.append(k)
            if k == 1:
                stop()

        with self.assertRaises(raises) as caught:
            lbmshape.morph(v, f, vt, ft, frames=24, res=24, steps=240, align="none", on_frame=on_frame)
        # Python alone would run its SIGINT handler only once the whole morph
        # had returned: every frame would have been made.
        self.assertGreaterEqual(len(seen), 2)
        self.assertLess(len(seen), 24)
        return caught.exception

    def test_ctrl_c_stops_the_morph_at_once_with_keyboard_interrupt(self):
        self.frames_made_stopping_at_frame_1(lambda: os.kill(os.getpid(), signal.SIGINT), KeyboardInterrupt)
        self.assertIs(signal.getsignal(signal.SIGINT), signal.default_int_handler, "Python's handler is back")
        v, f = icosphere(3)
        v2, f2 = lbmshape.denoise(v, f, res=24)  # nothing left standing
        self.assertGreater(len(f2), 0)

    def test_request_stop_from_another_thread_stops_the_calls_under_way(self):
        cancel = lambda: threading.Thread(target=lbmshape.request_stop).start()
        stopped = self.frames_made_stopping_at_frame_1(cancel, lbmshape.Interrupted)
        self.assertRegex(str(stopped), "^stopped: ")
        self.assertTrue(issubclass(lbmshape.Interrupted, lbmshape.Error))
        lbmshape.request_stop()  # with no call under way: stops nothing later
        v, f = icosphere(3)
        vt, ft = ellipsoid()
        frames = lbmshape.morph(v, f, vt, ft, frames=3, res=24, steps=20, align="none")
        self.assertEqual(len(frames), 3)

    def test_a_stop_of_its_own_stops_one_call_and_not_the_other(self):
        # Two morphs on threads of their own; the first's Stop is requested
        # from its frame 1: it alone stops, the other makes every frame.
        v, f = icosphere(3)
        vt, ft = ellipsoid()
        first, results = lbmshape.Stop(), {}

        def run(name, stop, on_frame):
            try:
                lbmshape.morph(v, f, vt, ft, frames=12, res=24, steps=240, align="none", on_frame=on_frame,
                               stop=stop)
                results[name] = "done"
            except lbmshape.Interrupted as e:
                results[name] = str(e)

        seen = {"first": [], "second": []}

        def first_frame(k, vk, fk):
            seen["first"].append(k)
            if k == 1:
                first.request()

        threads = [threading.Thread(target=run, args=("first", first, first_frame)),
                   threading.Thread(target=run, args=("second", lbmshape.Stop(),
                                                      lambda k, vk, fk: seen["second"].append(k)))]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        self.assertRegex(results["first"], "^stopped: ")
        self.assertLess(len(seen["first"]), 12)
        self.assertEqual(results["second"], "done")
        self.assertEqual(seen["second"], list(range(12)))
        self.assertTrue(first.requested)
        with self.assertRaises(lbmshape.Interrupted):  # a requested Stop stops a later call at once
            lbmshape.denoise(v, f, res=24, stop=first)
        self.assertGreater(len(lbmshape.denoise(v, f, res=24, stop=lbmshape.Stop())[1]), 0)


class IterMorph(unittest.TestCase):
    def test_the_frames_come_one_by_one_in_order(self):
        v, f = icosphere(3)
        vt, ft = ellipsoid()
        indices = [k for k, vk, fk in lbmshape.iter_morph(v, f, vt, ft, frames=5, res=24, steps=20, align="none")]
        self.assertEqual(indices, [0, 1, 2, 3, 4])

    def test_a_call_in_the_loop_on_the_morphs_own_device_is_refused(self):
        # It waited for the morph, which waited for the loop: a hang.
        v, f = icosphere(3)
        vt, ft = ellipsoid()
        device = lbmshape.Device()
        frames = lbmshape.iter_morph(v, f, vt, ft, frames=4, res=24, steps=40, align="none", device=device)
        try:
            for k, vk, fk in frames:
                with self.assertRaisesRegex(lbmshape.UsageError, "loop over a morph's frames cannot use"):
                    lbmshape.denoise(vk, fk, res=24, device=device)
                lbmshape.denoise(vk, fk, res=24, steps=1)  # the thread's own device
                break
        finally:
            frames.close()
        lbmshape.denoise(v, f, res=24, steps=1, device=device)  # the loop has ended: the device is free

    def test_leaving_early_stops_the_morph_and_the_device_is_free_again(self):
        v, f = icosphere(3)
        vt, ft = ellipsoid()
        for k, vk, fk in lbmshape.iter_morph(v, f, vt, ft, frames=40, res=24, steps=200, align="none"):
            if k == 1:
                break
        v2, f2 = lbmshape.denoise(v, f, res=24)
        self.assertGreater(len(f2), 0)

    def test_a_stop_given_to_the_loop_stops_the_morph(self):
        v, f = icosphere(3)
        vt, ft = ellipsoid()
        stop, seen = lbmshape.Stop(), []
        with self.assertRaisesRegex(lbmshape.Interrupted, "^stopped: "):
            for k, vk, fk in lbmshape.iter_morph(v, f, vt, ft, frames=40, res=24, steps=400, align="none",
                                                 stop=stop):
                seen.append(k)
                if k == 1:
                    stop.request()
        self.assertLess(len(seen), 40)

    def test_a_call_in_the_loop_runs_beside_the_morph(self):
        # The loop's thread has a default device of its own, so its call
        # does not wait for the morph, which waits for the loop.
        v, f = icosphere(3)
        vt, ft = ellipsoid()
        smoothed = [len(lbmshape.denoise(vk, fk, res=24)[1]) for k, vk, fk in
                    lbmshape.iter_morph(v, f, vt, ft, frames=4, res=24, steps=12, align="none")]
        self.assertEqual(len(smoothed), 4)
        self.assertTrue(all(n > 0 for n in smoothed))

    def test_an_error_of_the_morph_is_raised_by_the_loop(self):
        v, f = icosphere(3)
        with self.assertRaisesRegex(ValueError, "align must be"):
            for _ in lbmshape.iter_morph(v, f, v, f, align="left"):
                pass

    def test_what_the_generator_cannot_take_is_named(self):
        v, f = icosphere(2)
        with self.assertRaisesRegex(TypeError, "on_frame is lbmshape.morph"):
            next(lbmshape.iter_morph(v, f, v, f, on_frame=print))
        with self.assertRaisesRegex(TypeError, "use lbmshape.morph\\(..., report=True\\)"):
            next(lbmshape.iter_morph(v, f, v, f, report=True))


class Processes(unittest.TestCase):
    def test_triangles_may_be_nested_lists(self):
        v, f = icosphere(2)
        v2, f2 = lbmshape.denoise(v, f.tolist(), res=24, steps=1)
        self.assertTrue(closed(f2))
        with self.assertRaisesRegex(lbmshape.InputError, "beyond any mesh's vertices"):
            lbmshape.denoise(v, np.full((4, 3), 2**63, dtype=np.uint64), res=24)

    def test_a_forked_process_is_refused_rather_than_hanging(self):
        # The suite has made calls: a child forked now is refused at once
        # (it hung on OpenMP's threads, which fork() does not copy).
        v, f = icosphere(2)
        lbmshape.denoise(v, f, res=24, steps=1)
        read, write = os.pipe()
        pid = os.fork()
        if pid == 0:
            os.close(read)
            try:
                lbmshape.denoise(v, f, res=24, steps=1)
                os.write(write, b"ran")
            except lbmshape.UsageError as e:
                os.write(write, ("refused: " + str(e)).encode())
            finally:
                os._exit(0)
        os.close(write)
        _, status = os.waitpid(pid, 0)
        said = os.read(read, 4096).decode()
        os.close(read)
        self.assertTrue(said.startswith("refused: lbmshape cannot run in a process forked"), said)

    def test_the_program_may_end_with_a_morph_under_way(self):
        # A loop not finished, and a daemon thread's morph: the calls are
        # stopped at exit; the process aborted half the time before.
        import subprocess, sys
        script = (
            "import sys, threading, time\n"
            "sys.path.insert(0, %r)\n"
            "import lbmshape, numpy as np\n"
            "from test_lbmshape import icosphere\n"
            "v, f = icosphere(3)\n"
            "long = dict(frames=400, res=32, steps=8000, cs=0.0005, align='none')\n"
            "if sys.argv[2] == 'handler':\n"
            "    said = []\n"
            "    lbmshape.set_log_handler(lambda kind, message: said.append(message))\n"
            "if sys.argv[1] == 'loop':\n"
            "    g = lbmshape.iter_morph(v, f, v * [1.3, 1, 0.8], f, **long)\n"
            "    next(g)\n"
            "else:\n"
            "    threading.Thread(target=lambda: lbmshape.morph(v, f, v * [1.3, 1, 0.8], f, on_frame=lambda *a: None,"
            " **long), daemon=True).start()\n"
            "    time.sleep(1)\n"
        ) % os.path.dirname(lbmshape.__file__)
        # The same with a log handler, which a call stopped at exit still
        # calls from its own threads.
        for mode, log in (("loop", "stderr"), ("thread", "stderr"), ("loop", "handler"), ("thread", "handler")):
            r = subprocess.run([sys.executable, "-c", script, mode, log], cwd=os.path.dirname(__file__),
                               capture_output=True, text=True, timeout=120)
            self.assertEqual(r.returncode, 0, mode + ", " + log + ": " + r.stderr[-400:])


class Files(unittest.TestCase):
    def test_a_mesh_written_reads_back(self):
        v, f = icosphere(2)
        with tempfile.TemporaryDirectory() as folder:
            for name in ("s.obj", "s.ply", "s.glb"):
                path = os.path.join(folder, name)
                lbmshape.write_mesh(path, v, f)
                v2, f2 = lbmshape.read_mesh(path)
                self.assertEqual(f2.shape, f.shape, name)
                self.assertLess(np.abs(v2 - v).max(), 1e-6, name)

    def test_a_missing_file_is_an_input_error(self):
        with self.assertRaisesRegex(lbmshape.InputError, "no_such.obj"):
            lbmshape.read_mesh("/no/such/folder/no_such.obj")


if __name__ == "__main__":
    unittest.main()
