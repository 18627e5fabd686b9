"""pytest suite of the Python module `towdb` (python/towdb_module.cpp) on the
bundled database (db/towdb.sqlite).

Test plan:
  python-1  the README's main question: the dict carries the same numbers, bit
            for bit, as `towdb query --json` (one library, one C API), the
            database's vessel names, and the checks' margins (limit - value)
  python-2  query_many answers a list in order, each as query() alone would
  python-3  bad questions raise towdb.InputError naming the field (.field):
            unknown vessel, a string for a number, a missing field, an unknown key,
            heading 400, p = 1; outside the stored data towdb.OutOfRangeError (code 3)
  python-4  query_many(errors="record") answers the others and records the error
            on its question; errors="raise" raises
  python-5  query_frame: a pandas DataFrame, one row per question, same numbers
  python-6  a missing or non-towdb database raises towdb.DatabaseError; a closed
            handle raises towdb.Error
  python-7  max_speed / min_length: the value found passes both checks, and a bit
            beyond it the extreme-tension check fails or the search range ends
"""
import json
import math
import os
import sqlite3
import subprocess

import pytest

import towdb

SOURCE_DIR = os.environ["TOWDB_SOURCE_DIR"]
DB_PATH = os.path.join(SOURCE_DIR, "db", "towdb.sqlite")

# The README's main question (README.md, "Set up").
README_QUESTION = dict(tug="T-ATF", tow="FFG7", line="fiber", speed_kt=7, wind_kt=30, heading_deg=150,
                       length_ft=1200)


@pytest.fixture(scope="module")
def db():
    with towdb.Database(DB_PATH) as handle:
        yield handle


def cli_json(*args):
    out = subprocess.run([os.environ["TOWDB_EXE"], *args], capture_output=True, text=True, check=False)
    assert out.returncode in (0, 3), out.stderr
    return json.loads(out.stdout)


def test_readme_question_matches_the_cli(db):  # python-1
    a = db.query(**README_QUESTION)
    j = cli_json("query", "--db", DB_PATH, "--tug", "T-ATF", "--tow", "FFG7", "--line", "fiber", "--speed-kt", "7",
                 "--wind-kt", "30", "--heading-deg", "150", "--length-ft", "1200", "--json")
    assert (a["tug"], a["tow"]) == ("T-ATF 166", "FFG 7")
    for key in ("dynamic_tension_kips", "dynamic_999_kips", "mean_tension_lbf", "calculated_mean_tension_lbf",
                "extreme_tension_lbf", "breaking_strength_lbf", "uncertainty_kips", "interpolation_error_kips",
                "slack_fraction", "catenary_sag_ft", "catenary_depth_ft", "gumbel_u_kips", "gumbel_alpha_per_kip"):
        assert a[key] == j[key], key  # exact: the same library computes both
    extreme, mean = j["checks"]
    assert a["extreme_limit_lbf"] == extreme["limit_lbf"]
    assert a["extreme_margin_lbf"] == extreme["margin_lbf"]
    assert a["extreme_check_passed"] is extreme["passed"]
    assert a["mean_margin_percent"] == mean["margin_percent"]
    assert a["extreme_margin_lbf"] == a["extreme_limit_lbf"] - a["extreme_tension_lbf"]
    assert len(a["nearest_cases"]) == len(j["nearest_cases"])
    assert a["interpolation_space"] == j["interpolation_space"]


def test_hs_is_answered_through_the_equivalent_wind(db):  # python-1b
    # EQ-QUERY-10: Hs = 0.2092 U^2 / g; 30 kt = 15.433 m/s -> 5.0811 m = 16.670 ft.
    by_hs = db.query(**{k: v for k, v in README_QUESTION.items() if k != "wind_kt"}, hs_ft=16.67035)
    assert abs(by_hs["equivalent_wind_kt"] - 30.0) < 1e-3
    assert any(w["kind"] == "equivalent_wind" for w in by_hs["warnings"])  # named as by `towdb query --json`
    assert abs(by_hs["dynamic_999_kips"] / db.query(**README_QUESTION)["dynamic_999_kips"] - 1.0) < 1e-4
    assert db.query(**README_QUESTION)["equivalent_wind_kt"] is None


def test_query_many_answers_in_order(db):  # python-2
    questions = [dict(README_QUESTION, heading_deg=h) for h in (0, 90, 180)]
    answers = db.query_many(questions)
    assert [a["heading_deg"] for a in answers] == [0.0, 90.0, 180.0]
    for q, a in zip(questions, answers):
        assert a["extreme_tension_lbf"] == db.query(q)["extreme_tension_lbf"]


@pytest.mark.parametrize("change, field, error", [
    (dict(tug="Hercules"), "tug", towdb.InputError),
    (dict(speed_kt="fast"), "speed_kt", towdb.InputError),
    (dict(length_ft=None), "length_ft", towdb.InputError),
    (dict(colour="red"), "colour", towdb.InputError),
    (dict(heading_deg=400), "heading_deg", towdb.InputError),
    (dict(probability=1.0), "probability", towdb.InputError),
    (dict(extrapolate="yes"), "extrapolate", towdb.InputError),
    (dict(speed_kt=30), "speed_kt", towdb.OutOfRangeError),
])
def test_bad_questions_name_the_field(db, change, field, error):  # python-3
    with pytest.raises(error) as info:
        db.query(dict(README_QUESTION, **change))
    assert info.value.field == field
    assert field in str(info.value)
    assert isinstance(info.value, ValueError)
    assert info.value.code == (3 if error is towdb.OutOfRangeError else 2)


def test_out_of_range_says_the_stored_range(db):  # python-3
    with pytest.raises(towdb.OutOfRangeError, match=r"speed_kt = 30 is outside the stored range \[5, 9\]"):
        db.query(dict(README_QUESTION, speed_kt=30))


def test_query_many_records_or_raises(db):  # python-4
    questions = [README_QUESTION, dict(README_QUESTION, tow="Nimitz"), dict(README_QUESTION, speed_kt=8)]
    answers = db.query_many(questions, errors="record")
    assert "error" not in answers[0] and "error" not in answers[2]
    assert answers[1]["error_field"] == "tow" and answers[1]["error_code"] == 2
    assert "Nimitz" in answers[1]["error"] and answers[1]["tow"] == "Nimitz"
    with pytest.raises(towdb.InputError):
        db.query_many(questions)
    with pytest.raises(towdb.InputError, match="errors = 'ignore'"):
        db.query_many(questions, errors="ignore")


def test_query_frame_is_a_dataframe(db):  # python-5
    pandas = pytest.importorskip("pandas")  # a test dependency (scripts/install-deps.sh): present in CI
    questions = [dict(README_QUESTION, speed_kt=s) for s in (5, 6, 7)] + [dict(README_QUESTION, tug="X")]
    frame = db.query_frame(questions)
    assert isinstance(frame, pandas.DataFrame)
    assert len(frame) == 4
    assert list(frame["speed_kt"][:3]) == [5.0, 6.0, 7.0]
    assert frame["extreme_tension_lbf"][2] == db.query(README_QUESTION)["extreme_tension_lbf"]
    assert frame["error_field"][3] == "tug"
    assert "nearest_cases" not in frame.columns


def test_bad_databases(tmp_path):  # python-6
    with pytest.raises(towdb.DatabaseError):
        towdb.Database(str(tmp_path / "absent.sqlite"))
    other = tmp_path / "other.sqlite"
    sqlite3.connect(other).execute("CREATE TABLE t (x)").connection.commit()
    with pytest.raises(towdb.DatabaseError):
        towdb.open(str(other))
    with pytest.raises(towdb.InputError, match="space = 'cubic'"):
        towdb.Database(DB_PATH, space="cubic")


def test_closed_handle_raises(db):  # python-6
    handle = towdb.Database(DB_PATH)
    handle.close()
    with pytest.raises(towdb.Error, match="closed"):
        handle.query(README_QUESTION)


def test_inverse_searches(db):  # python-7
    question = {k: v for k, v in README_QUESTION.items() if k != "speed_kt"}
    s = db.max_speed(question)
    assert s["found"]
    low, high = s["searched_speed_kt"]
    assert low <= s["max_speed_kt"] <= high
    at = s["at_value"]
    assert at["speed_kt"] == s["max_speed_kt"]
    assert at["extreme_check_passed"] and at["mean_check_passed"]
    if s["max_speed_kt"] < high - 0.05:  # just beyond: a check fails, or the tugs' capacity binds
        beyond = db.query(dict(question, speed_kt=s["max_speed_kt"] + 0.05))
        capacity = any(w["kind"] == "above_tug_capacity" for w in beyond["warnings"])
        assert not (beyond["extreme_check_passed"] and beyond["mean_check_passed"]) or capacity
    q = {k: v for k, v in README_QUESTION.items() if k != "length_ft"}
    m = db.min_length(q)
    assert m["found"] and m["at_value"]["extreme_check_passed"]
    assert m["searched_length_ft"][0] <= m["min_length_ft"] <= m["searched_length_ft"][1]
    assert math.isfinite(m["at_value"]["catenary_sag_ft"])
    assert math.isfinite(m["at_value"]["catenary_depth_ft"])  # schema 6: every bundled fit has its lowest point
