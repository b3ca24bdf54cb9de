; Bracket pairs of AIDL (CAD) for Zed (matching, rainbow brackets)
("(" @open ")" @close)
("[" @open "]" @close)
("{" @open "}" @close)
