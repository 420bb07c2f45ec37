// Fixture: a header the transport fixture includes.
#pragma once
