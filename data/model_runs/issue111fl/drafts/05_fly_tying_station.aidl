# Request: a fly-tying station from 6 mm ply, five parts. A base of two glued layers, each
# 300 x 180 with R10 corners. The top layer has a 92 mm pocket for the vise's pedestal
# (centre 80 left of the middle, 10 in front of it), a 60 x 40 (R5) bead and hook well
# (centre 60 right, 20 back), and a row of eight 12 mm tool holes through both layers, 18
# apart from the middle to the right, 60 in front of the centre line; along the front edge
# an engraved 0-120 mm ruler (tick every 2 mm, longer and numbered every 10). A back panel
# 300 wide standing 150 above the base, its back face 4 mm in from the base's back edge, on
# three tenons through the top layer; in it two rows of six 8 mm holes for spool dowels
# (50 apart, 60 and 110 above the base) and "TIGHT LINES" engraved above them. Two gussets,
# 10 mm in from the ends, 100 deep in front of the back panel, sloping from its top down
# to 30 high at the front, each with tenons into the top layer and through the back panel.

units mm
thickness 6 mm
import "std/joints.aidl"

T = 6 mm
BACK_Y = 90 mm - 4 mm - T / 2       # the back panel's middle
BACK_H = 150 mm                     # above the base
GX = 150 mm - 10 mm                 # the gussets' middles
G_D = 100 mm
FRONT_Y = BACK_Y - T / 2 - G_D      # the gussets' front ends

def layer(top=true) -> solid {
    slab = RoundedRectangle(center=(0, 0), width=300 mm, height=180 mm, corner_radius=10 mm)
    for i in range(8) {
        hole tool { c = Circle(center=(i * 18 mm, -60 mm), diameter=12 mm) }
    }
    if top {
        hole pedestal { c = Circle(center=(-80 mm, -10 mm), diameter=92 mm) }
        hole well { r = RoundedRectangle(center=(60 mm, 20 mm), width=60 mm, height=40 mm, corner_radius=5 mm) }
        back = tab_and_slot(part="slot", length=300 mm, thickness=T, tabs=3, tab=40 mm, screw=0,
                            cx=0 mm, cy=BACK_Y)
        g_l = tab_and_slot(part="slot", length=G_D, thickness=T, tabs=2, tab=20 mm, screw=0,
                           rotation=90 deg, cx=-GX, cy=FRONT_Y + G_D / 2)
        g_r = tab_and_slot(part="slot", length=G_D, thickness=T, tabs=2, tab=20 mm, screw=0,
                           rotation=90 deg, cx=GX, cy=FRONT_Y + G_D / 2)
        drawing ruler {
            for k in range(61) {
                tick = Line((k * 2 mm, -90 mm), (k * 2 mm, -90 mm + (7 mm if k % 5 == 0 else 3.5 mm)))
            }
            for k in range(13) {
                num = Text(str(k * 10), position=(k * 10 mm, -81 mm), size=3 mm)
            }
        }
    }
}

# drawn on its side: x is the world's y (front to back), y is height from the bottom layer's top
def gusset() -> solid {
    body = Polygon([(FRONT_Y, 0), (BACK_Y - T / 2, 0), (BACK_Y - T / 2, T), (BACK_Y + T / 2, T),
                    (BACK_Y + T / 2, T + BACK_H), (BACK_Y - T / 2, T + BACK_H), (FRONT_Y, T + 30 mm)])
    foot = tab_and_slot(part="tab", length=G_D, thickness=T, tabs=2, tab=20 mm, screw=0,
                        rotation=180 deg, cx=FRONT_Y + G_D / 2, cy=0 mm)
    back = tab_and_slot(part="tab", length=BACK_H, thickness=T, tabs=2, tab=30 mm, screw=0,
                        rotation=-90 deg, cx=BACK_Y + T / 2, cy=T + BACK_H / 2)
}

assembly station {
    bottom = layer(top=false)
    top = layer(top=true)
    g_left = gusset()
    g_right = gusset()

    # drawn standing: y up from the bottom layer's top (the tenons' tips)
    solid back {
        body = RoundedRectangle(bottom_left=(-150 mm, 0), width=300 mm, height=T + BACK_H,
                                corner_radii=[10 mm, 10 mm, 0, 0])
        foot = tab_and_slot(part="tab", length=300 mm, thickness=T, tabs=3, tab=40 mm, screw=0,
                            rotation=180 deg, cx=0 mm, cy=0 mm)
        g_l = tab_and_slot(part="slot", length=BACK_H, thickness=T, tabs=2, tab=30 mm, screw=0,
                           rotation=90 deg, cx=-GX, cy=T + BACK_H / 2)
        g_r = tab_and_slot(part="slot", length=BACK_H, thickness=T, tabs=2, tab=30 mm, screw=0,
                           rotation=90 deg, cx=GX, cy=T + BACK_H / 2)
        for row in [60 mm, 110 mm] {
            for i in range(6) {
                hole spool { c = Circle(center=(-125 mm + i * 50 mm, T + row), diameter=8 mm) }
            }
        }
        drawing motto { t = Text("TIGHT LINES", position=(0, T + 135 mm), size=10 mm) }
    }

    # flat, for cutting
    RightOf(top, bottom, gap=10 mm)
    AlignBottom(top, bottom)
    Above(back, bottom, gap=10 mm)
    AlignLeft(back, bottom)
    RightOf(g_left, back, gap=10 mm)
    AlignBottom(g_left, back)
    RightOf(g_right, g_left, gap=10 mm)
    AlignBottom(g_right, back)

    # assembled
    Place(bottom, position=(0, 0, 0), face="up")
    Place(top, position=(0, 0, T), face="up")
    Place(back, position=(0, BACK_Y + T / 2, T), face="front", up="up")
    Place(g_left, position=(-GX - T / 2, 0, T), face="right", up="up")
    Place(g_right, position=(GX - T / 2, 0, T), face="right", up="up")

    assert top.slab.bb.width == 300 mm and top.slab.bb.height == 180 mm, "layers 300 x 180"
    assert top.pedestal.c.diameter == 92 mm, "92 mm pedestal pocket"
    assert len(top.tool) == 8 and len(bottom.tool) == 8, "eight tool holes through both layers"
    assert top.tool[1].c.center.x - top.tool[0].c.center.x == 18 mm, "tool holes 18 apart"
    assert len(top.ruler.num) == 13, "ruler numbered 0..120"
    assert back.body.bb.height - 6 mm == 150 mm, "back panel 150 above the base"
    assert top.slab.bb.top - (top.back.slot[0].bb.top) == 4 mm, "back face 4 mm in from the back edge"
    assert len(back.spool) == 2 and len(back.spool[0]) == 6, "two rows of six spool holes"
    assert g_left.body.bb.width - 6 mm == 100 mm, "gussets 100 deep in front of the back panel"
    assert top.slab.bb.right - top.g_r.slot[0].bb.center_x == 10 mm, "gussets 10 in from the ends"
}
