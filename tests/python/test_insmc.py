"""The Python entry (apps/python/insmc.py) against the command line it wraps:
a study's records equal run.json's envelope, a sweep's rows carry the swept
values, bad input raises InsmcError with insmc's own line and exit code 2."""
import json
import os
import subprocess
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "apps", "python"))
import insmc  # noqa: E402


class PythonEntry(unittest.TestCase):
    def test_a_study_is_the_command_lines_run_json(self):
        study = insmc.run(samples=2000, scheme="none,5.4", system=1)
        with tempfile.TemporaryDirectory() as d:
            subprocess.run([insmc.program(), "run", "--samples=2000", "--scheme=none,5.4", "--system=1", "--quiet",
                            "--out", d], check=True)
            with open(os.path.join(d, "run.json")) as f:
                on_disk = json.load(f)
        self.assertEqual(study["envelope"], on_disk["envelope"])
        records = insmc.rows(study)
        self.assertEqual(len(records), len(on_disk["envelope"]))
        horizontal = [r for r in records if r["axis"] == "horizontal" and r["t_min"] == 84]
        self.assertEqual({r["scheme"] for r in horizontal}, {"none", "5.4"})
        self.assertTrue(all(r["rms_lo_m"] <= r["rms_m"] <= r["rms_hi_m"] for r in records))

    def test_a_sweep_gives_rows_with_the_swept_values(self):
        sweep = insmc.run(samples=2000, scheme="none", system=1, test_duration=["5min", "10min"])
        records = insmc.rows(sweep)
        self.assertEqual(sorted({r["test_duration_s"] for r in records}), [300, 600])

    def test_covariance_and_options_with_lists(self):
        cov = insmc.covariance(scheme="none", system=1, bound=["gyro_drift=20meru"])
        self.assertEqual(cov["settings"]["uncertainties"]["gyro_drift_x"]["bound_si"], 20 * 7.292115e-8)
        self.assertTrue(all(r["rms_m"] > 0 for r in insmc.rows(cov)))

    def test_bad_input_raises_with_insmcs_line(self):
        with self.assertRaises(insmc.InsmcError) as caught:
            insmc.run(samples=0)
        self.assertEqual(caught.exception.exit_code, 2)
        self.assertIn("--samples", str(caught.exception))


if __name__ == "__main__":
    unittest.main()
