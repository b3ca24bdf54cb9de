# Request: An opening-hours sign for the glass door of my bike repair shop, from 3 mm plywood:
# a plate 200 x 150 mm with 10 mm rounded corners and two 5 mm holes for suction hooks, centred
# 10 mm in from the top and side edges. Engraved: a border line 5 mm inside the edge (5 mm
# corner radius); the title "OPENING HOURS" in bold filled letters 12 mm tall, centred, its
# baseline 25 mm below the top edge; a rule under it 32 mm below the top edge, 150 mm long;
# then seven rows, Monday to Sunday, 8 mm tall, baselines 13 mm apart, the first 50 mm below the
# top edge: the day at the left (starting 20 mm from the left edge), its hours at the right
# (ending 20 mm from the right edge): MON-FRI 9:00 - 18:00, SAT 10:00 - 16:00, SUN CLOSED.

units mm
thickness 3 mm

param row_pitch = 13 mm, min = 11 mm, max = 15 mm

W = 200 mm
H = 150 mm
DAYS = ["MONDAY", "TUESDAY", "WEDNESDAY", "THURSDAY", "FRIDAY", "SATURDAY", "SUNDAY"]
HOURS = ["9:00 - 18:00", "9:00 - 18:00", "9:00 - 18:00", "9:00 - 18:00", "9:00 - 18:00",
         "10:00 - 16:00", "CLOSED"]

solid sign {
    plate = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=10)
    for i in range(2) {
        hole hook {
            c = Circle(center=((i * 2 - 1) * (W / 2 - 10), H / 2 - 10), diameter=5)
        }
    }
    # everything engraved is written in the plate's own coordinates (its centre at 0, 0)
    drawing face {
        border = RoundedRectangle(center=(0, 0), width=W - 10, height=H - 10, corner_radius=5)
        title = Text("OPENING HOURS", position=(0, H / 2 - 25), size=12, font="sans:Bold",
                     fill=true)
        rule = Line((-75, H / 2 - 32), (75, H / 2 - 32))
        for i in range(7) {
            day = Text(DAYS[i], position=(-W / 2 + 20, H / 2 - 50 - i * row_pitch), size=8,
                       anchor="start")
            time = Text(HOURS[i], position=(W / 2 - 20, H / 2 - 50 - i * row_pitch), size=8,
                        anchor="end")
        }
    }

    assert len(face.day) == 7 and len(face.time) == 7, "seven rows"
    assert abs(plate.width - 200 mm) < 0.001 mm and abs(plate.height - 150 mm) < 0.001 mm, "plate 200 x 150"
    assert abs(hook[0].c.diameter - 5 mm) < 0.001 mm, "5 mm holes"
    assert abs(plate.bb.top - hook[1].c.center.y - 10 mm) < 0.001 mm and
        abs(plate.bb.right - hook[1].c.center.x - 10 mm) < 0.001 mm, "holes 10 mm in"
    assert abs(plate.bb.top - face.title.position.y - 25 mm) < 0.001 mm, "title baseline 25 mm down"
    assert abs(face.rule.length - 150 mm) < 0.001 mm, "rule 150 long"
    assert abs(face.day[0].position.y - face.day[1].position.y - 13 mm) < 0.001 mm, "rows 13 mm apart"
    assert abs(plate.bb.top - face.day[0].position.y - 50 mm) < 0.001 mm, "first row 50 mm down"
    assert abs(face.day[0].bb.left - plate.bb.left - 20 mm) < 0.5 mm, "days start 20 mm in"
    assert abs(plate.bb.right - face.time[0].bb.right - 20 mm) < 0.5 mm, "hours end 20 mm in"
    # the rows clear each other across the middle, and the last clears the border
    assert min([face.time[i].bb.left - face.day[i].bb.right for i in range(7)]) > 5 mm, "day and hours apart"
    assert face.day[6].bb.bottom > face.border.bb.bottom + 3 mm, "last row inside the border"
    assert face.title.bb.bottom > face.rule.start.y + 2 mm, "title above the rule"
    assert face.title.bb.left > hook[0].bb.right + 3 mm and face.title.bb.right < hook[1].bb.left - 3 mm,
        "title clear of the hook holes"
    assert HOURS[6] == "CLOSED" and HOURS[5] == "10:00 - 16:00" and HOURS[0] == "9:00 - 18:00", "hours"
}
