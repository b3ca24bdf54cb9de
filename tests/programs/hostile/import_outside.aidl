# expect: E0114 2:8
import "../../../../../../../../../../etc/passwd"
solid s { c = Circle((0, 0), 1) }
