class NotApplicable(Exception): pass
