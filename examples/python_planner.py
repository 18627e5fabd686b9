#!/usr/bin/env python3
"""A tow planner's session with the Python module `towdb`, notebook style.

Run from the repository root after building (the module is build/python/towdb*.so):

    PYTHONPATH=build/python python3 examples/python_planner.py db/towdb.sqlite

Each block below is a notebook cell: one question, the same question over a
range of headings, the fastest speed that passes the Navy Towing Manual
checks, and a table (pandas, when installed).
"""
import sys

import towdb

db_path = sys.argv[1] if len(sys.argv) > 1 else "db/towdb.sqlite"
db = towdb.open(db_path)
print(f"{db.path}: {db.case_count} cases, interpolation in {db.space} space")

# --- one question: the README's (T-ATF 166 towing FFG 7 on 1,200 ft of fiber) ---
question = dict(tug="T-ATF", tow="FFG7", line="fiber", speed_kt=7, wind_kt=30, heading_deg=150, length_ft=1200)
a = db.query(question)
print(f"{a['tug']} towing {a['tow']}: extreme tension {a['extreme_tension_lbf']:,.0f} lbf "
      f"(dynamic {a['dynamic_tension_kips']:.1f} +/- {a['uncertainty_kips']:.1f} kips at mean "
      f"{a['mean_tension_lbf']:,.0f} lbf); BS/1.5 = {a['extreme_limit_lbf']:,.0f} lbf, "
      f"margin {a['extreme_margin_lbf']:,.0f} lbf ({a['extreme_margin_percent']:.1f} %)")

# --- the same question at every 30 deg of heading ---
for h, r in zip(range(0, 181, 30), db.query_many([dict(question, heading_deg=h) for h in range(0, 181, 30)])):
    status = "pass" if r["extreme_check_passed"] and r["mean_check_passed"] else "FAIL"
    print(f"  heading {h:3d} deg: {r['extreme_tension_lbf'] / 1000:6.1f} kips  {status}")

# --- the fastest speed that passes both checks within the tugs' capacity ---
search = db.max_speed({k: v for k, v in question.items() if k != "speed_kt"})
if search["found"]:
    print(f"fastest passing speed: {search['max_speed_kt']:.2f} kt "
          f"(searched {search['searched_speed_kt'][0]:g}-{search['searched_speed_kt'][1]:g} kt)")
else:
    print("no speed in the stored range passes")

# --- errors name the field ---
try:
    db.query(dict(question, speed_kt=30))
except towdb.OutOfRangeError as e:
    print(f"refused ({e.field}): {e}")

# --- a table, when pandas is installed ---
try:
    frame = db.query_frame([dict(question, speed_kt=s) for s in (5, 6, 7, 8, 9)])
    print(frame[["speed_kt", "mean_tension_lbf", "extreme_tension_lbf", "uncertainty_kips",
                 "extreme_check_passed"]].to_string(index=False))
except ImportError as e:
    print(f"(no table: {e})")
db.close()
