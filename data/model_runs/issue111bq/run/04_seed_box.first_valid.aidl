# Request: a box to file seed packets by season for the garden shed shelf, 3 mm ply.
# Outside 300 long x 120 wide x 90 high, open top, finger-jointed (10 mm fingers), with
# three dividers across making four equal compartments (spring, summer, autumn, winter);
# the dividers only 60 mm high so the packets' names show. The long front wall is engraved
# with the season over each compartment (8 mm letters, 25 mm below the top edge), and the
# long back wall with "SEEDS" in filled bold 24 mm letters, centred.
units mm
thickness 3 mm
import "std/boxes.aidl"

T = 3 mm
LEN = 300 mm
SEASONS = ["SPRING", "SUMMER", "AUTUMN", "WINTER"]
# compartment pitch: four compartments and three dividers in the inside length
PITCH = (LEN - 2 * T + T) / 4

assembly seed_box {
    box = divider_tray(length=LEN, width=120 mm, height=90 mm, rows=1, cols=4, thickness=T,
                       finger=10 mm, clearance=0.2 mm, divider_height=60 mm)

    drawing seasons {
        for i in range(4) {
            t = Text(SEASONS[i], position=((i - 1.5) * PITCH, 0), size=8, valign="middle")
        }
    }
    CutInto(seasons, box.body.front)
    seasons.t[0].position.x == box.body.front.bb.center_x - 1.5 * PITCH
    seasons.t[0].position.y == box.body.front.bb.top - 25 mm

    drawing title {
        w = Text("SEEDS", position=(0, 0), size=24, font="sans:Bold", valign="middle", fill=true)
    }
    CutInto(title, box.body.back)
    At(title.w.position, box.body.back.bb.center)

    assert len(SEASONS) == 4, "four seasons"
    assert len(box.col_divider) == 3, "three dividers across"
    assert box.body.front.bb.top - seasons.t[3].position.y == 25 mm, "labels 25 below the top"
    assert seasons.t[3].position.x - seasons.t[0].position.x == 3 * PITCH, "one per compartment"
}
