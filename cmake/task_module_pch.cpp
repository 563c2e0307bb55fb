// The object whose compile makes the task modules' precompiled header (task_module_pch.h).
